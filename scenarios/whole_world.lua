-- Whole-world traffic: writes a BlueSky scenario (.scn) with N flights in the
-- air at t = 0 between airports of airports.dat, plus the departures and
-- arrivals of the next HORIZON seconds, for `squawk scn`, `squawk serve` and
-- the REPL (IC FILE.scn) to load.
--
--   squawk run scenarios/whole_world.lua [N] [HORIZON_S] [NAME.scn] [quiet] \
--       --navdata DIR --out DIR [--seed S]
--
-- N (default 3750): flights airborne at t = 0; HORIZON_S (default 3600): the
-- scenario's length [s]; NAME.scn (default whole_world.scn) is written into
-- --out; it prints its path and counts unless `quiet`. Same seed, same file.
--
-- Flights: origin and destination drawn by airport size (Large 10, Medium 1;
-- Small, Closed and the rest never), 300-14 000 km apart on the great circle.
-- The type and cruise level follow the distance: regional below 700 km
-- (FL180-260, 250 kt CAS), narrow-body to 4 500 km (FL300-390, Mach 0.78),
-- wide-body beyond (FL330-410, Mach 0.84), odd levels eastbound and even
-- levels westbound (the semicircular rule). Airborne flights start at a
-- random point of their great circle, cruising towards the destination
-- (ADDWPT on its position: LNAV flies the great circle). Departures appear at
-- their origin at 2 000 ft over the horizon, at the rate that keeps about N
-- airborne, and climb (ALT) to their level at 250 kt, taking their cruise
-- speed after 10 minutes. A flight is deleted (DEL) at its
-- estimated arrival time when that falls within the horizon.
local N = math.tointeger(tonumber(arg[1] or "3750"))
local horizon = tonumber(arg[2] or "3600")
local name = arg[3] or "whole_world.scn"
assert(N and N >= 0, "N: expected a whole number of flights >= 0, got '" .. tostring(arg[1]) .. "'")
assert(horizon and horizon >= 0, "HORIZON_S: expected seconds >= 0, got '" .. tostring(arg[2]) .. "'")
assert(squawk.navdata_dir, "no navdata: give --navdata DIR (BlueSky's navdata with airports.dat)")
assert(squawk.out_dir, "no output folder: give --out DIR")

local R = 6371000.0 -- [m] earth radius
local rad = math.pi / 180

-- Airports: code, lat, lon [deg], weight.
local weights = { Large = 10, Medium = 1 }
local airports, cum = {}, {}
local total = 0
for line in io.lines(squawk.navdata_dir .. "/airports.dat") do
  if line:sub(1, 1) ~= "#" then
    local code, _, lat, lon, class = line:match("^([^,]*),([^,]*),([^,]*),([^,]*),%s*([^,]*)")
    local w = weights[class or ""]
    lat, lon = tonumber(lat), tonumber(lon)
    if w and lat and lon then
      airports[#airports + 1] = { code = code, lat = lat, lon = lon }
      total = total + w
      cum[#cum + 1] = total
    end
  end
end
assert(#airports > 1, squawk.navdata_dir .. "/airports.dat: expected Large and Medium airports, found "
  .. #airports)

local function pick()
  local x, lo, hi = math.random() * total, 1, #cum
  while lo < hi do
    local mid = (lo + hi) // 2
    if cum[mid] < x then lo = mid + 1 else hi = mid end
  end
  return airports[lo]
end

-- Great circle: central angle [rad], point at fraction f, initial bearing [deg].
local function angle(a, b)
  local p1, p2 = a.lat * rad, b.lat * rad
  local dp, dl = p2 - p1, (b.lon - a.lon) * rad
  local h = math.sin(dp / 2) ^ 2 + math.cos(p1) * math.cos(p2) * math.sin(dl / 2) ^ 2
  return 2 * math.asin(math.min(1, math.sqrt(h)))
end
local function along(a, b, d, f)
  local s1, s2 = math.sin((1 - f) * d) / math.sin(d), math.sin(f * d) / math.sin(d)
  local p1, l1, p2, l2 = a.lat * rad, a.lon * rad, b.lat * rad, b.lon * rad
  local x = s1 * math.cos(p1) * math.cos(l1) + s2 * math.cos(p2) * math.cos(l2)
  local y = s1 * math.cos(p1) * math.sin(l1) + s2 * math.cos(p2) * math.sin(l2)
  local z = s1 * math.sin(p1) + s2 * math.sin(p2)
  return { lat = math.atan(z, math.sqrt(x * x + y * y)) / rad, lon = math.atan(y, x) / rad }
end
local function bearing(a, b)
  local p1, p2, dl = a.lat * rad, b.lat * rad, (b.lon - a.lon) * rad
  local y = math.sin(dl) * math.cos(p2)
  local x = math.cos(p1) * math.sin(p2) - math.sin(p1) * math.cos(p2) * math.cos(dl)
  return (math.atan(y, x) / rad) % 360
end

-- ISA true airspeed [m/s] of a speed in the scenario's terms at altitude h [m]:
-- Mach below 1, CAS [kt] otherwise (low-altitude approximation: TAS = CAS
-- (rho0 / rho)^0.5).
local function tas(spd, h)
  local T = math.max(216.65, 288.15 - 0.0065 * h)
  if spd < 1 then return spd * math.sqrt(1.4 * 287.05 * T) end
  local rho = 1.225 * (T / 288.15) ^ 4.256
  if h > 11000 then rho = 0.3639 * math.exp(-(h - 11000) / 6341.6) end
  return spd * 0.514444 * math.sqrt(1.225 / rho)
end

local classes = {
  { upto = 700e3, types = { "AT76", "DH8D", "E190", "CRJ9" }, fl = { 180, 260 }, spd = 250 },
  { upto = 4500e3, types = { "A320", "B738", "A321", "A20N", "B38M", "A319" }, fl = { 300, 390 }, spd = 0.78 },
  { upto = math.huge, types = { "B77W", "A359", "B789", "A333", "B744", "A388" }, fl = { 330, 410 }, spd = 0.84 },
}

-- One flight: origin, destination, distance [m], class, level [FL].
local function flight()
  while true do
    local o, d = pick(), pick()
    local ang = angle(o, d)
    local dist = ang * R
    if dist >= 300e3 and dist <= 14000e3 then
      local c
      for _, k in ipairs(classes) do
        if dist < k.upto then c = k break end
      end
      local east = bearing(o, d) < 180
      -- Levels 20 FL apart, odd hundreds eastbound, even westbound.
      local lo = c.fl[1] // 20 * 20 + (east and 10 or 0)
      local steps = (c.fl[2] - lo) // 20
      local fl = lo + 20 * math.random(0, steps)
      return { o = o, d = d, ang = ang, dist = dist, c = c, fl = fl, type = c.types[math.random(#c.types)] }
    end
  end
end

local lines = {}
local function at(t, text)
  lines[#lines + 1] = { t = t, n = #lines, text = text }
end
local function stamp(t)
  return string.format("%02d:%02d:%05.2f", math.floor(t / 3600), math.floor(t % 3600 / 60), t % 60)
end
local function spd_text(s) return s < 1 and string.format("%.2f", s) or tostring(s) end

local flights, duration_sum = 0, 0
local function add(f, t0, frac, alt_fl)
  flights = flights + 1
  local id = string.format("W%05d", flights)
  local p = frac > 0 and along(f.o, f.d, f.ang, frac) or f.o
  local hdg = bearing(p, f.d)
  local v = tas(f.c.spd, f.fl * 30.48)
  local climbing = alt_fl ~= f.fl
  local spd = climbing and 250 or f.c.spd
  at(t0, string.format("CRE %s %s %.5f %.5f %.1f FL%03d %s", id, f.type, p.lat, p.lon, hdg, alt_fl, spd_text(spd)))
  at(t0, string.format("ADDWPT %s %.5f %.5f", id, f.d.lat, f.d.lon))
  at(t0, string.format("LNAV %s ON", id))
  if climbing then
    at(t0, string.format("ALT %s FL%03d", id, f.fl))
    if spd ~= f.c.spd then at(t0 + 600, string.format("SPD %s %s", id, spd_text(f.c.spd))) end
  end
  local arrive = t0 + (1 - frac) * f.dist / v
  if arrive <= horizon then at(arrive, "DEL " .. id) end
  return f.dist / v
end

at(0, "ASAS ON")
for _ = 1, N do
  local f = flight()
  duration_sum = duration_sum + add(f, 0, 0.02 + 0.96 * math.random(), f.fl)
end
-- Departures: N flights of mean duration T leave at N / T per second.
if N > 0 then
  local rate = N / (duration_sum / N)
  local t = 0
  while true do
    t = t - math.log(1 - math.random()) / rate
    if t > horizon then break end
    add(flight(), t, 0, 20)
  end
end

table.sort(lines, function(a, b)
  if a.t ~= b.t then return a.t < b.t end
  return a.n < b.n
end)
local path = squawk.out_dir .. "/" .. name
local out = assert(io.open(path, "w"))
out:write(string.format("# Whole-world traffic: %d flights airborne at 0, %d in all over %g s (seed %d).\n",
  N, flights, horizon, squawk.seed))
out:write("# Written by scenarios/whole_world.lua from " .. squawk.navdata_dir .. "/airports.dat\n")
for _, l in ipairs(lines) do out:write(stamp(l.t), ">", l.text, "\n") end
assert(out:close())
if arg[4] ~= "quiet" then print(string.format("%s: %d flights (%d airborne at 0), %d commands", path, flights, N, #lines)) end
