local ok, err = pcall(squawk.env.new, arg[1])
print(ok, err)
