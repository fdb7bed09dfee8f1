// Conformance: every file of BlueSky's scenario folder runs headless with
// BlueSky's navdata, without a crash. The test runs 30 s of sim time per file
// to stay fast; SQUAWK_CONFORMANCE_FULL=1 runs the real sweep (to the last
// command or one hour) and prints the README tables, as
// `squawk scn DIR --conformance` does.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>

#include "command/conformance.h"

using namespace squawk;
using namespace squawk::command;
namespace fs = std::filesystem;

TEST_CASE("conformance: BlueSky's scenario files run with zero crashes" * doctest::test_suite("shared")) {
  const fs::path root = fs::path(SQUAWK_SHARED_DIR) / "bluesky";
  if (!fs::is_directory(root / "scenario") || !fs::is_directory(root / "navdata")) {
    MESSAGE("skipped: " << root.string() << "/{scenario,navdata} not found (BlueSky data is optional)");
    return;
  }
  auto db = NavDb::load((root / "navdata").string());
  REQUIRE(db);
  ScenarioRunOptions opts;
  opts.navdb = *db;
  const char* full = std::getenv("SQUAWK_CONFORMANCE_FULL");
  opts.max_sim_time = full && *full == '1' ? 3600.0 : 30.0;
  const ConformanceReport rep = run_conformance((root / "scenario").string(), opts);
  MESSAGE("max_sim_time " << opts.max_sim_time << " s\n" << conformance_markdown(rep));
  CHECK(rep.files == 324);  // the .scn files; Florent/florentnew.scn.txt is not one
  CHECK(rep.loaded == rep.files);
  CHECK(rep.fully_run == rep.files);
  CHECK(rep.executed > 15000);
  // Unknown commands are skipped by name, never counted as executed.
  CHECK(rep.skipped.count("PAN") == 1);
  CHECK(rep.skipped.count("ALT") == 0);
}
