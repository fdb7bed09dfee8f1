-- A policy that raises (tests/gym_policies.sh).
local P = {}
function P:act(obs) error("no luck") end
return P
