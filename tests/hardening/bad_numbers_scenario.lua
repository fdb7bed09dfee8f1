-- A scenario with numbers no integer holds (issue 12 sibling of point 18).
return { env = { intruders = 0 / 0 }, train = { episodes = 1e300 } }
