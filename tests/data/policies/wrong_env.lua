-- A policy for another environment (tests/gym_policies.sh).
return {env = "MergeEnv-v0", act = function(self, obs) return {0, 0} end}
