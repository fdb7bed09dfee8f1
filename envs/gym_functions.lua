-- BlueSky-Gym's polygon helpers (bluesky_gym/envs/common/functions.py at
-- aed26d6, cited as F<line>) in Lua, each operation in numpy's order; its
-- get_point_at_distance (F24-42) is squawk.geo.destination. numpy's sin and
-- cos differ from the C library's in the last bit for most arguments
-- (8 593 of 8 892 points of get_point_at_distance, measured), so replayed
-- points agree to about 1e-15 deg, not bit for bit.
local F = {}

-- F44-59: a point {x, y} on the circle of radius r, at an angle drawn
-- uniformly (draws: a gym_draws object).
function F.random_point_on_circle(r, draws)
  local alpha = 2 * math.pi * draws:uniform()
  return {r * math.cos(alpha), r * math.sin(alpha)}
end

-- F61-75: in place, by angle atan2(y, x), ascending.
function F.sort_points_clockwise(p)
  table.sort(p, function(a, b) return math.atan(a[2], a[1]) < math.atan(b[2], b[1]) end)
end

-- F77-96: the shoelace area.
function F.polygon_area(p)
  local area, n = 0.0, #p
  for i = 1, n do
    local q = p[i % n + 1]
    area = area + (p[i][1] * q[2] - p[i][2] * q[1])
  end
  return math.abs(area) / 2.0
end

-- F98-114: a point {x, y} [NM] (x north, y east) about `lat, lon` [deg] as lat, lon.
function F.nm_to_latlong(lat, lon, point)
  return lat + point[1] / 60, lon + point[2] / (60 * math.cos(math.rad(lat)))
end

return F
