// scenarios/whole_world.lua: the whole-world traffic generator, run in the
// sandbox as `squawk run` does, and its scenario loaded and run by a stack.
// Needs BlueSky's airports.dat (../shared/bluesky/navdata); skips without it.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "command/stack.h"
#include "core/files.h"
#include "core/paths.h"
#include "script/vm.h"

namespace fs = std::filesystem;
using namespace squawk;

namespace {
// Writes the scenario of `n` airborne flights over `horizon` s with `seed`
// into `dir`/`name` and returns its text.
std::string generate(const std::string& nav, const std::string& dir, const std::string& name, int n,
                     int horizon, uint64_t seed) {
  script::VmOptions vo;
  vo.seed = seed;
  vo.out_dir = dir;
  vo.navdata_dir = nav;
  script::Vm vm(vo);
  const Status st = vm.run_file(paths::resource("scenarios/whole_world.lua"),
                                {std::to_string(n), std::to_string(horizon), name, "quiet"});
  REQUIRE_MESSAGE(st.is_ok(), st.message());
  auto text = files::read(dir + "/" + name);
  REQUIRE(text);
  return *text;
}
}  // namespace

TEST_CASE("whole_world.lua: seeded flights between airports that a stack loads and flies") {
  const fs::path nav = fs::path(SQUAWK_SHARED_DIR) / "bluesky" / "navdata";
  if (!fs::exists(nav / "airports.dat")) {
    MESSAGE("skipped: " << (nav / "airports.dat").string() << " not found (BlueSky navdata is optional)");
    return;
  }
  const std::string dir = (fs::temp_directory_path() / ("squawk_ww_" + std::to_string(::getpid()))).string();
  REQUIRE(files::make_dirs(dir).is_ok());
  const std::string a = generate(nav.string(), dir, "a.scn", 300, 900, 3);
  CHECK(generate(nav.string(), dir, "b.scn", 300, 900, 3) == a);  // same seed, same file
  CHECK(generate(nav.string(), dir, "c.scn", 300, 900, 4) != a);

  // Every CRE at t = 0 cruises at a level of the semicircular rule (odd
  // hundreds of feet eastbound, even westbound); later ones are departures.
  std::istringstream in(a);
  std::string line;
  int airborne = 0, departures = 0, deletions = 0, odd_rule = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const bool at0 = line.rfind("00:00:00.00>", 0) == 0;
    const std::string cmd = line.substr(line.find('>') + 1);
    if (cmd.rfind("DEL ", 0) == 0) ++deletions;
    if (cmd.rfind("CRE ", 0) != 0) continue;
    std::istringstream f(cmd);
    std::string cre, id, type, fl;
    double lat = 0, lon = 0, hdg = 0;
    f >> cre >> id >> type >> lat >> lon >> hdg >> fl;
    CHECK(std::fabs(lat) <= 90.0);
    CHECK(std::fabs(lon) <= 180.0);
    if (!at0) {
      ++departures;
      CHECK(fl == "FL020");
      continue;
    }
    ++airborne;
    const int level = std::stoi(fl.substr(2));
    CHECK(level >= 180);
    CHECK(level <= 410);
    // The heading at the start point need not match the departure bearing
    // that chose the level; count rather than require.
    odd_rule += ((level / 10) % 2 == 1) == (hdg < 180.0);
  }
  CHECK(airborne == 300);
  CHECK(departures > 0);
  CHECK(deletions > 0);
  CHECK(odd_rule > 240);

  command::Stack st(0);
  st.set_base_dir(dir);
  REQUIRE(st.load_scenario(dir + "/a.scn").is_ok());
  REQUIRE(st.run_until(900.0).is_ok());
  CHECK(st.tally().failed.empty());
  CHECK(st.sim().n() == airborne + departures - deletions);
  CHECK(st.sim().cd_settings().enabled);
  std::error_code ec;
  fs::remove_all(dir, ec);
}
