-- A scenario whose Lua reward runs a few hundred instructions per call.
return {
  reward = function(f)
    local r = 0
    for i = 1, 100 do r = r + i * 0 end
    return f.intrusions > 0 and -1 or r
  end,
}
