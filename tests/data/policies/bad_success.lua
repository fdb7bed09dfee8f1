-- An environment whose info.success is not a boolean (tests/gym_policies.sh).
local E = {id = "BadSuccess-v0", observation = {{name = "x", size = 1}}, action = {low = {-1}, high = {1}},
           max_episode_steps = 3}
function E:reset(seed) return {0} end
function E:step(action) return {0}, 0, true, false, {success = 1} end
return E
