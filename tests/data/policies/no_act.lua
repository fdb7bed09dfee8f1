-- A policy file without act (tests/gym_policies.sh).
return {env = "DescentEnv-v0"}
