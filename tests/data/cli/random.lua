for _ = 1, 3 do print(math.random()) end
print(math.random(1, 100))
