check_eq(1 + 1, 2)
check_near(math.sqrt(2), 1.41421356, 1e-8)
