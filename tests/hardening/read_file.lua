-- Point 5: prints the first line of arg[1] (the sandbox decides whether it may).
local f = assert(io.open(arg[1]))
print(f:read("l"))
print("key=" .. tostring(os.getenv("SQUAWK_LLM_API_KEY")))
