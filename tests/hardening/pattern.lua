-- Point 6: a string pattern that backtracks for hours inside one C call.
print(string.find(string.rep("a", 20000), ".-.-.-.-b"))
