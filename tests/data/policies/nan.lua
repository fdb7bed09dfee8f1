-- A non-finite action (tests/gym_policies.sh).
return {act = function(self, obs) return {0 / 0} end}
