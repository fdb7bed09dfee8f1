-- reset that is not a function (tests/gym_policies.sh).
return {reset = 1, act = function(self, obs) return {0} end}
