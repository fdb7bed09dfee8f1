-- Point 7: the budget is per call of the reward function, not per process:
-- 3000 calls of ~400 instructions each pass a 200000-instruction limit.
local e = squawk.env.new(arg[1], "train")
local steps, seed = 0, 0
while steps < 3000 do
  if e:reset(seed) then
    repeat
      e:step(0)
      steps = steps + 1
    until select(2, e:step(0)) or steps >= 3000
  end
  seed = seed + 1
end
print("steps " .. steps)
