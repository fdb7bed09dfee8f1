-- numpy's global random draws for a BlueSky-Gym environment written in Lua:
-- from the engine's seeded generator, or, to replay a recorded BlueSky-Gym
-- episode (bench/gym_ref/compare.py), from a list of the values numpy drew,
-- in the order the environment asks for them.
--
--   local draws = require("gym_draws").new(seed, options and options.draws)
--   draws:randint(lo, hi)  -- np.random.randint(lo, hi): a whole number in [lo, hi)
--   draws:uniform()        -- np.random.uniform(0, 1): a number in [0, 1)
local Draws = {}
Draws.__index = Draws

function Draws.new(seed, recorded)
  math.randomseed(seed)
  return setmetatable({recorded = recorded, n = 0}, Draws)
end

-- The next recorded value, or nil when drawing from the generator.
function Draws:replayed()
  if not self.recorded then return nil end
  self.n = self.n + 1
  return assert(self.recorded[self.n], "options.draws ran out: the recording has " .. #self.recorded .. " values")
end

function Draws:randint(lo, hi)
  return self:replayed() or math.random(lo, hi - 1)
end

function Draws:uniform()
  return self:replayed() or math.random()
end

return Draws
