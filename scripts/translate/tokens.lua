-- Word-level rewriting of a request before the grammar reads it.
local M = {}

-- `toks` are the words of `text` (split at spaces). at(i) -> replacement, next: tokens
-- i..next-1 become `replacement`; nil keeps token i. Returns the words joined by single
-- spaces where anything was rewritten, else `text` itself.
function M.rewrite(text, toks, at)
  local out, i = nil, 1  -- out: the words so far, from the first rewrite on
  while i <= #toks do
    local rep, nxt = at(i)
    if rep then
      out = out or table.move(toks, 1, i - 1, 1, {})
      out[#out + 1], i = rep, nxt
    else
      if out then out[#out + 1] = toks[i] end
      i = i + 1
    end
  end
  return out and table.concat(out, " ") or text
end

return M
