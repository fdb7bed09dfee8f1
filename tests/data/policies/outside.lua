-- An action outside the box (tests/gym_policies.sh).
return {act = function(self, obs) return {1.5} end}
