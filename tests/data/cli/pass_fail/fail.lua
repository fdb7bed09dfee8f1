check_eq(2 + 2, 5, "arithmetic")
