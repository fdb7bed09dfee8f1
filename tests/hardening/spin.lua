-- Point 6: a loop stopped by the wall clock alone.
while true do end
