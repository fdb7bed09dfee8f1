-- Word-level rewriting of a request before the grammar reads it.
local M = {}

-- `toks` are the words of `text` (split at spaces). at(i) -> replacement, next: tokens
-- i..next-1 become `replacement`; nil keeps token i. Returns the words joined by single
-- spaces where anything was rewritten, else `text` itself.
function M.rewrite(text, toks, at)
  local out, i, changed = {}, 1, false
  while i <= #toks do
    local rep, nxt = at(i)
    if rep then
      out[#out + 1], i, changed = rep, nxt, true
    else
      out[#out + 1], i = toks[i], i + 1
    end
  end
  return changed and table.concat(out, " ") or text
end

return M
