local mod = require "mod"
print(mod.run(3))
