-- Accuracy floors of the offline translation graph, scored right / asked /
-- wrong (wrong: a command issued that is not the expected one, or a command
-- where a question was expected). The held-out sentences (tests/data:
-- translate_heldout.tsv, translate_fresh.tsv) were each written before the
-- grammar was tuned against them and are never tuned on row by row; the shared
-- corpora are read from ../shared/corpora when present, else skipped.
local graph = require("translate.graph")
local nodes = require("translate.nodes")

-- Airports (DEST EHAM) validate only with navdata: BlueSky's, when present.
local NAV = "../shared/bluesky/navdata"
local has_nav = pcall(squawk.sim.new, { navdata = NAV })  -- false when absent or not readable
local function sim_for(setup)
  local sim = has_nav and squawk.sim.new({ navdata = NAV }) or squawk.sim.new()
  for _, line in ipairs(nodes.split_commands(setup)) do sim:exec(line) end
  return sim
end

-- Right / asked / wrong as eval-translate counts them: one scorer,
-- translate::evaluate (engine/translate/corpus.cpp), through
-- squawk.translate.evaluate; the translator here runs each case on a sim
-- with navdata when it is present.
local function score(path)
  local r = squawk.translate.evaluate(path, function(c)
    return graph.translate(c.utterance,
      { mode = "offline", sim = sim_for(c.setup), waypoints = nodes.defined_waypoints(c.setup) })
  end)
  return r.right / r.cases, r.wrong / r.cases, r.cases
end

-- needs_nav: the corpus names real fixes and airports, so its figures hold
-- only with BlueSky's navdata (it is skipped, saying so, without it).
local function floors(path, min_right, max_wrong, needs_nav)
  if needs_nav and not has_nav then
    print("skipped: " .. path .. " names real fixes and airports: its floors need BlueSky's navdata at " .. NAV)
    return
  end
  local ok, right, wrong, n = pcall(score, path)
  if not ok then
    local msg = tostring(right)
    -- only the shared corpora may be absent; the repository's own must be read
    local shared = path:find("^%.%./shared/") ~= nil
    if shared and (msg:find("cannot open", 1, true) or msg:find("not allowed", 1, true)) then
      print("skipped: " .. path .. " is absent or not readable (the shared corpora live beside the "
        .. "repository; ctest allows reading ../shared)")
      return
    end
    error(right, 0)
  end
  print(string.format("%s: %d cases, right %.1f %%, wrong %.1f %%", path, n, 100 * right, 100 * wrong))
  check(right >= min_right, string.format("%s: right %.3f below %.3f", path, right, min_right))
  check(wrong <= max_wrong, string.format("%s: wrong %.3f above %.3f", path, wrong, max_wrong))
end

-- Rounds written by writers who never saw the grammar (docs/translator_trust.md):
-- kept here after their first-sight figures were recorded (docs/translation_ledger.md),
-- fixed by class; floors at the figures reached (right at least, wrong at most).
floors("tests/data/translate_round1.tsv", 0.995, 0.0, true)
floors("tests/data/translate_round2.tsv", 0.933, 0.0032, true)
floors("tests/data/translate_round3.tsv", 0.970, 0.0037, true)
floors("tests/data/translate_round4.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round5.tsv", 0.983, 0.0, true)
floors("tests/data/translate_round6.tsv", 1, 0.0, true)
floors("tests/data/translate_round7.tsv", 0.992, 0.0036, true)
floors("tests/data/translate_round8.tsv", 0.977, 0.0, true)
floors("tests/data/translate_round9.tsv", 0.981, 0.0075, true)
floors("tests/data/translate_round10.tsv", 0.973, 0.0, true)
floors("tests/data/translate_round11.tsv", 0.989, 0.0, true)
floors("tests/data/translate_round12.tsv", 0.992, 0.0, true)
floors("tests/data/translate_round13.tsv", 0.981, 0.0, true)
floors("tests/data/translate_round14.tsv", 0.950, 0.0, true)
floors("tests/data/translate_round15.tsv", 0.993, 0.0035, true)
floors("tests/data/translate_round16.tsv", 0.931, 0.0, true)
floors("tests/data/translate_round17.tsv", 1, 0.0, true)
floors("tests/data/translate_round18.tsv", 0.973, 0.0, true)
floors("tests/data/translate_round19.tsv", 0.983, 0.0043, true)
floors("tests/data/translate_round20.tsv", 0.985, 0.0, true)
floors("tests/data/translate_round21.tsv", 1, 0.0, true)
floors("tests/data/translate_round22.tsv", 1, 0.0, true)
floors("tests/data/translate_round23.tsv", 0.985, 0.0, true)
floors("tests/data/translate_round24.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round25.tsv", 0.943, 0.0, true)
floors("tests/data/translate_round26.tsv", 1, 0.0, true)
floors("tests/data/translate_round27.tsv", 0.955, 0.0, true)
floors("tests/data/translate_round28.tsv", 1, 0.0, true)
floors("tests/data/translate_round29.tsv", 0.990, 0.0033, true)
floors("tests/data/translate_round30.tsv", 0.991, 0.0, true)
floors("tests/data/translate_round31.tsv", 0.978, 0.0, true)
floors("tests/data/translate_round32.tsv", 0.991, 0.0, true)
floors("tests/data/translate_round33.tsv", 0.973, 0.0027, true)
floors("tests/data/translate_round34.tsv", 0.988, 0.0, true)
floors("tests/data/translate_round35.tsv", 0.982, 0.0036, true)
floors("tests/data/translate_round36.tsv", 0.928, 0.0, true)
floors("tests/data/translate_round37.tsv", 0.996, 0.0033, true)
floors("tests/data/translate_round38.tsv", 0.988, 0.0, true)
floors("tests/data/translate_round39.tsv", 0.992, 0.0, true)
floors("tests/data/translate_round40.tsv", 0.964, 0.0072, true)
floors("tests/data/translate_round41.tsv", 0.983, 0.0041, true)
floors("tests/data/translate_round42.tsv", 0.991, 0.0, true)
floors("tests/data/translate_round43.tsv", 0.988, 0.0, true)
floors("tests/data/translate_round44.tsv", 0.993, 0.0, true)
floors("tests/data/translate_round45.tsv", 0.979, 0.0, true)
floors("tests/data/translate_round46.tsv", 0.963, 0.0, true)
floors("tests/data/translate_round47.tsv", 0.966, 0.0038, true)
floors("tests/data/translate_round48.tsv", 0.988, 0.0, true)
floors("tests/data/translate_round49.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round50.tsv", 0.970, 0.0, true)
floors("tests/data/translate_round51.tsv", 0.992, 0.0, true)
floors("tests/data/translate_round52.tsv", 0.945, 0.0, true)
floors("tests/data/translate_round53.tsv", 0.979, 0.0, true)
floors("tests/data/translate_round54.tsv", 0.863, 0.0, true)
floors("tests/data/translate_round55.tsv", 0.968, 0.0, true)
floors("tests/data/translate_round56.tsv", 0.987, 0.0, true)
floors("tests/data/translate_round57.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round58.tsv", 0.950, 0.0, true)
floors("tests/data/translate_round59.tsv", 0.983, 0.0033, true)
floors("tests/data/translate_round60.tsv", 0.980, 0.0, true)
floors("tests/data/translate_round61.tsv", 0.978, 0.0, true)
floors("tests/data/translate_round62.tsv", 0.978, 0.0, true)
floors("tests/data/translate_round63.tsv", 0.992, 0.0, true)
floors("tests/data/translate_round64.tsv", 0.974, 0.0037, true)
floors("tests/data/translate_round65.tsv", 0.996, 0.0035, true)
floors("tests/data/translate_round66.tsv", 0.982, 0.0036, true)
floors("tests/data/translate_round67.tsv", 0.989, 0.0, true)
floors("tests/data/translate_round68.tsv", 0.963, 0.0, true)
floors("tests/data/translate_round69.tsv", 0.988, 0.0, true)
floors("tests/data/translate_round70.tsv", 0.977, 0.0, true)
floors("tests/data/translate_round71.tsv", 0.979, 0.0, true)
floors("tests/data/translate_round72.tsv", 0.977, 0.0, true)
floors("tests/data/translate_round73.tsv", 0.933, 0.0268, true)
floors("tests/data/translate_round74.tsv", 0.976, 0.0, true)
floors("tests/data/translate_round75.tsv", 0.989, 0.0, true)
floors("tests/data/translate_round76.tsv", 0.949, 0.0, true)
floors("tests/data/translate_round77.tsv", 0.980, 0.0, true)
floors("tests/data/translate_round78.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round79.tsv", 0.996, 0.0034, true)
floors("tests/data/translate_round80.tsv", 0.955, 0.0, true)
floors("tests/data/translate_round81.tsv", 0.961, 0.0, true)
floors("tests/data/translate_round82.tsv", 0.958, 0.0161, true)
floors("tests/data/translate_round83.tsv", 0.920, 0.0, true)
floors("tests/data/translate_round84.tsv", 0.958, 0.0035, true)
floors("tests/data/translate_round85.tsv", 0.979, 0.0120, true)
floors("tests/data/translate_round86.tsv", 0.965, 0.0, true)
floors("tests/data/translate_round87.tsv", 1, 0.0, true)
floors("tests/data/translate_round88.tsv", 0.964, 0.0, true)
floors("tests/data/translate_round89.tsv", 0.892, 0.0, true)
floors("tests/data/translate_round90.tsv", 0.961, 0.0065, true)
floors("tests/data/translate_round91.tsv", 0.986, 0.0, true)
floors("tests/data/translate_round92.tsv", 0.982, 0.0069, true)
floors("tests/data/translate_round93.tsv", 0.986, 0.0034, true)
floors("tests/data/translate_round94.tsv", 0.977, 0.0, true)
floors("tests/data/translate_round95.tsv", 1, 0.0, true)
floors("tests/data/translate_round96.tsv", 0.987, 0.0033, true)
floors("tests/data/translate_round97.tsv", 0.975, 0.0070, true)  -- (cycle 61: "FL2 70", "fl 2 10" asked, a split level)
floors("tests/data/translate_round98.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round99.tsv", 0.981, 0.0073, true)
floors("tests/data/translate_round100.tsv", 1, 0.0, true)
floors("tests/data/translate_round101.tsv", 0.993, 0.0, true)
floors("tests/data/translate_round102.tsv", 0.990, 0.0031, true)
floors("tests/data/translate_round103.tsv", 0.984, 0.0, true)
floors("tests/data/translate_round104.tsv", 1, 0.0, true)
floors("tests/data/translate_round105.tsv", 0.979, 0.0, true)
floors("tests/data/translate_round106.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round107.tsv", 0.979, 0.0035, true)
floors("tests/data/translate_round108.tsv", 0.974, 0.0108, true)
floors("tests/data/translate_round109.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round110.tsv", 0.997, 0.0, true)
floors("tests/data/translate_round111.tsv", 1, 0.0, true)
floors("tests/data/translate_round112.tsv", 0.962, 0.0, true)
floors("tests/data/translate_round113.tsv", 0.989, 0.0070, true)
floors("tests/data/translate_round114.tsv", 0.992, 0.0037, true)
-- (r115-067, "maintain 180 knots until four d m e", expects a question: a limit until the final's 3 to 6 miles is
-- flown by decision, docs/translation_ledger.md cycle 49, so the row is wrong by that decision)
floors("tests/data/translate_round115.tsv", 0.965, 0.0115, true)
floors("tests/data/translate_round116.tsv", 0.980, 0.0034, true)
floors("tests/data/translate_round117.tsv", 0.966, 0.0, true)
floors("tests/data/translate_round118.tsv", 0.892, 0.0, true)
floors("tests/data/translate_round119.tsv", 0.993, 0.0, true)
floors("tests/data/translate_round120.tsv", 0.956, 0.0200, true)
floors("tests/data/translate_round121.tsv", 0.904, 0.0375, true)
floors("tests/data/translate_round122.tsv", 0.973, 0.0066, true)
-- (r123-212, "move Flyer 73R ten miles further east", expects ASK: with "Flyer" read it is MOVE, Cycle 50's offset)
floors("tests/data/translate_round123.tsv", 0.970, 0.0067, true)
floors("tests/data/translate_round124.tsv", 0.992, 0.0037, true)
floors("tests/data/translate_round125.tsv", 0.911, 0.0038, true)
floors("tests/data/translate_round126.tsv", 0.883, 0.0110, true)
floors("tests/data/translate_round127.tsv", 0.993, 0.0, true)
floors("tests/data/translate_round128.tsv", 0.921, 0.0038, true)
floors("tests/data/translate_round129.tsv", 0.966, 0.0271, true)
floors("tests/data/translate_round130.tsv", 0.940, 0.0134, true)
floors("tests/data/translate_round131.tsv", 0.917, 0.0035, true)
floors("tests/data/translate_round132.tsv", 0.885, 0.0, true)
floors("tests/data/translate_round133.tsv", 0.992, 0.0, true)
floors("tests/data/translate_round134.tsv", 0.830, 0.0102, true)
floors("tests/data/translate_round135.tsv", 0.881, 0.0136, true)
floors("tests/data/translate_round136.tsv", 0.855, 0.0073, true)
floors("tests/data/translate_round137.tsv", 0.971, 0.0036, true)
floors("tests/data/translate_round138.tsv", 0.884, 0.0035, true)
floors("tests/data/translate_round139.tsv", 0.963, 0.0, true)
floors("tests/data/translate_round140.tsv", 0.875, 0.0068, true)
floors("tests/data/translate_round141.tsv", 0.990, 0.0034, true)
floors("tests/data/translate_round142.tsv", 0.926, 0.0, true)
floors("tests/data/translate_round143.tsv", 0.813, 0.0034, true)
floors("tests/data/translate_round144.tsv", 0.970, 0.0037, true)
floors("tests/data/translate_round145.tsv", 0.929, 0.0034, true)
floors("tests/data/translate_round146.tsv", 0.891, 0.0038, true)  -- (r146-133: E175 is E75L, by decision)
floors("tests/data/translate_round147.tsv", 0.982, 0.0035, true)
floors("tests/data/translate_round148.tsv", 0.931, 0.0035, true)
floors("tests/data/translate_round149.tsv", 0.992, 0.0, true)
floors("tests/data/translate_round150.tsv", 0.879, 0.0101, true)
floors("tests/data/translate_round151.tsv", 0.966, 0.0034, true)
floors("tests/data/translate_round152.tsv", 0.837, 0.0, true)
floors("tests/data/translate_round153.tsv", 0.983, 0.0034, true)
floors("tests/data/translate_round154.tsv", 0.888, 0.0035, true)
floors("tests/data/translate_round155.tsv", 0.851, 0.0039, true)
floors("tests/data/translate_round156.tsv", 0.897, 0.0069, true)
floors("tests/data/translate_round157.tsv", 0.974, 0.0065, true)
floors("tests/data/translate_round158.tsv", 0.969, 0.0169, true)
floors("tests/data/translate_round159.tsv", 0.812, 0.0, true)
floors("tests/data/translate_round160.tsv", 0.939, 0.0034, true)
floors("tests/data/translate_round161.tsv", 0.905, 0.0068, true)
floors("tests/data/translate_round162.tsv", 0.989, 0.0, true)
floors("tests/data/translate_round163.tsv", 0.922, 0.0, true)
floors("tests/data/translate_round164.tsv", 0.986, 0.0034, true)
-- (r165-060 "Eastflight four lima bravo": an airline word squawk does not know before the flight number, asked:
-- docs/translator_trust.md, cycle 57)
floors("tests/data/translate_round165.tsv", 0.790, 0.0035, true)
floors("tests/data/translate_round166.tsv", 0.969, 0.0, true)
floors("tests/data/translate_round167.tsv", 0.976, 0.0, true)
floors("tests/data/translate_round168.tsv", 0.950, 0.0032, true)
floors("tests/data/translate_round169.tsv", 0.904, 0.0037, true)
floors("tests/data/translate_round170.tsv", 0.957, 0.0036, true)
floors("tests/data/translate_round171.tsv", 0.935, 0.0, true)
floors("tests/data/translate_round172.tsv", 0.940, 0.0, true)
floors("tests/data/translate_round173.tsv", 0.931, 0.0115, true)
floors("tests/data/translate_round174.tsv", 0.981, 0.0112, true)
floors("tests/data/translate_round175.tsv", 0.954, 0.0, true)
floors("tests/data/translate_round176.tsv", 0.968, 0.0029, true)
floors("tests/data/translate_round177.tsv", 0.839, 0.0183, true)
floors("tests/data/translate_round178.tsv", 0.982, 0.0036, true)
floors("tests/data/translate_round179.tsv", 0.831, 0.0220, true)
floors("tests/data/translate_round180.tsv", 0.966, 0.0076, true)
floors("tests/data/translate_round181.tsv", 0.982, 0.0036, true)
floors("tests/data/translate_round182.tsv", 0.967, 0.0182, true)
floors("tests/data/translate_round183.tsv", 0.970, 0.0073, true)
floors("tests/data/translate_round184.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round185.tsv", 0.973, 0.0134, true)
floors("tests/data/translate_round186.tsv", 0.966, 0.0112, true)
floors("tests/data/translate_round187.tsv", 0.982, 0.0035, true)
floors("tests/data/translate_round188.tsv", 0.996, 0.0038, true)
floors("tests/data/translate_round189.tsv", 0.946, 0.0032, true)
floors("tests/data/translate_round190.tsv", 0.951, 0.0075, true)
floors("tests/data/translate_round191.tsv", 0.992, 0.0076, true)
floors("tests/data/translate_round192.tsv", 0.994, 0.0028, true)
floors("tests/data/translate_round193.tsv", 0.992, 0.0, true)
floors("tests/data/translate_round194.tsv", 0.918, 0.0069, true)
floors("tests/data/translate_round195.tsv", 0.993, 0.0034, true)
floors("tests/data/translate_round196.tsv", 0.955, 0.0111, true)
floors("tests/data/translate_round197.tsv", 0.974, 0.0073, true)
floors("tests/data/translate_round198.tsv", 0.996, 0.0, true)
floors("tests/data/translate_round199.tsv", 0.977, 0.0193, true)
floors("tests/data/translate_round200.tsv", 0.954, 0.0035, true)
floors("tests/data/translate_round201.tsv", 0.957, 0.0194, true)
floors("tests/data/translate_round202.tsv", 0.976, 0.0201, true)
floors("tests/data/translate_heldout.tsv", 0.95, 0.01)
floors("tests/data/translate_fresh.tsv", 0.95, 0.01)
floors("../shared/corpora/nl2trafscript_dev.tsv", 0.98, 0.01)
-- vice: one aircraft per row, its callsign and fix names garbled by speech recognition; a
-- callsign not heard exactly is asked about with one aircraft flying too
-- (lexicon.callsign_confirm.alone: 84 rows), a fix name not heard exactly is confirmed, the only
-- known name too (lexicon.waypoint_confirm: 25 rows); these rows score as asked (a navaid said by
-- its navdata name won 5 back); a word the recogniser garbled ("December eighteen five thousand",
-- "Fighting two seven zero") is asked about by name (lexicon.accounted: 66 rows)
-- (ten speech-recognition garbles of an airline's name before a flight number that matches, "Peco Six Forty
-- Seven", asked since cycle 57: docs/translator_trust.md)
floors("../shared/corpora/vice_trafscript.tsv", 0.547, 0.0044)

-- squawk.translate.evaluate is eval-translate's scorer: a translator that always asks is right
-- exactly on the rows that expect a question, never wrong; one that issues a command where a
-- question was expected is wrong there; an error names the case
do
  local path = "tests/data/translate_heldout.tsv"
  local asks = 0
  for _, c in ipairs(squawk.translate.corpus(path)) do if c.expected == "ASK" then asks = asks + 1 end end
  local r = squawk.translate.evaluate(path, function() return { commands = {}, ask = "which?" } end)
  check_eq(string.format("%d %d %d %d", r.cases, r.right, r.asked, r.wrong),
    string.format("76 %d %d 0", asks, 76 - asks))
  r = squawk.translate.evaluate(path, function() return { commands = { "HOLD" } } end)
  check_eq(r.wrong, 76 - r.right)
  check(r.wrong >= asks, "a command where a question was expected is wrong")
  local ok, err = pcall(squawk.translate.evaluate, path, function(c) error("boom at " .. c.id) end)
  check(not ok and tostring(err):find("h001", 1, true) ~= nil, tostring(err))
end
