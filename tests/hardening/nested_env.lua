-- Point 4: a scenario that loads itself through squawk.env.new.
squawk.env.new("tests/hardening/nested_env.lua")
return {}
