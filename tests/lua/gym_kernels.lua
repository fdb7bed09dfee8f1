-- The kernels Lua environments call per step: squawk.geo, the SI sim
-- kernels, and squawk.gym.load of a shipped environment.
local geo = squawk.geo

local one_deg_nm = 6371000 * math.pi / 180 / 1852   -- kwikdist: R = 6371 km, 1852 m per NM
check_near(geo.kwikdist(52, 4, 53, 4), one_deg_nm, 1e-9, "kwikdist one degree north")
local qdr, d = geo.kwikqdrdist(52, 4, 52, 5)
check_near(qdr, 90, 1e-9, "due east")
check_near(d, one_deg_nm * math.cos(math.rad(52)), 1e-9, "east distance scales with cos(lat)")
local lat, lon = geo.kwikpos(52, 4, 0, 60)
check_near(lat, 53, 1e-12, "kwikpos: 60 NM per degree")
check_near(lon, 4, 1e-12)
check_eq(geo.gym_wrap180(190), -170)
check_eq(geo.gym_wrap180(-190), 170)
check_eq(geo.wrap360(-90), 270)

-- head-on at 100 m/s closing, 10 km apart, 5 NM zone
local tcpa, dcpa, t_in, t_out = geo.cpa(10000, 0, -100, 0, 9260)
check_near(tcpa, 100, 1e-9)
check_near(dcpa, 0, 1e-6)
check_near(t_in, 7.4, 1e-9)
check_near(t_out, 192.6, 1e-9)
local _, miss, none = geo.cpa(10000, 20000, -100, 0, 9260)
check_near(miss, 20000, 1e-6, "passes 20 km abeam")
check_eq(none, nil, "no entry time when the tracks miss the zone")
local ok, err = pcall(geo.cpa, 0, 0, 1, 1, 0)
check(not ok and err:find("radius r must be > 0"), err)

local square = {0, 0, 0, 1, 1, 1, 1, 0}
check_eq(geo.inside(0.5, 0.5, square), true)
check_eq(geo.inside(1.5, 0.5, square), false)
ok, err = pcall(geo.inside, 0, 0, {0, 0, 1})
check(not ok and err:find("at least 3 points"), err)

-- SI kernels: create at CAS 150 m/s, select a climb, read back
local s = squawk.sim.new{}
s:exec("DT 1")
s:create{id = "KL001", type = "A320", lat = 52, lon = 4, alt_m = 3000, spd = 150}
local la, lo, alt, hdg, tas, gs, vs, cas = s:values("KL001")
check_eq(la, 52); check_eq(lo, 4); check_eq(alt, 3000); check_eq(hdg, 0); check_eq(vs, 0)
check_near(cas, 150, 1e-9, "spd is CAS in m/s")
check(tas > cas, "true airspeed above CAS at 3000 m")
check_eq(gs, tas)
s:select_vertical("KL001", 1000000, -5)   -- the magnitude is flown toward the selected altitude
s:step(30)
local _, _, alt2, _, _, _, vs2 = s:values("KL001")
check_near(vs2, 5, 1e-9, "climbs at |vs|")
check(alt2 > 3000 + 100, "climbed")
ok, err = pcall(s.values, s, "NOPE")
check(not ok and err:find("no aircraft 'NOPE'"), err)
s:creconfs{id = "I1", type = "A320", target = "KL001", dpsi_deg = 90, dcpa_m = 0, tlosh_s = 300, dh_m = 500}
local ila, ilo, ialt = s:values("I1")
check_near(ialt, alt2 + 500, 1e-9, "creconfs: the intruder at the target's altitude + dH")
local _, dist_nm = geo.kwikqdrdist(la, lo, ila, ilo)
check(dist_nm > 5, "creconfs: outside the zone 300 s before the loss of separation")
ok, err = pcall(s.creconfs, s, {id = "I2", type = "A320", target = "KL001"})
check(not ok and err:find("dpsi_deg, dcpa_m and tlosh_s are required"), err)
s:delete_all()
check_eq(s:count(), 0)

-- a shipped environment loads as a table with the Gymnasium-shaped API
local env = squawk.gym.load(squawk.home .. "/envs/descent.lua")
check_eq(env.id, "DescentEnv-v0")
local obs = env:reset(1)
check_eq(#obs, 4)
local o2, r, term, trunc = env:step({0.5})
check_eq(#o2, 4); check(r <= 0); check_eq(term, false); check_eq(trunc, false)
