-- Two numbers for a one-number action (tests/gym_policies.sh).
return {act = function(self, obs) return {0, 0} end}
