-- Points 6 and 18: evaluate's episodes are bounded and checked.
squawk.env.evaluate{ scenario = "scenarios/horizontal_cr.lua", policy = "zero", episodes = load("return " .. arg[1])() }
