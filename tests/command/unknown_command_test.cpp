// Unknown names in a scenario: a typo fails at its file:line with the closest
// registry command; BlueSky's display and plugin commands stay a listed skip;
// commands queued by a scenario line (SCHEDULE, conditions) report that line.
#include <doctest/doctest.h>

#include <filesystem>

#include "command/bluesky_only.h"
#include "command/registry.h"
#include "command/stack.h"
#include "core/files.h"

using namespace squawk;
using namespace squawk::command;
namespace fs = std::filesystem;

TEST_CASE("registry: the closest command to an unknown name, within one or two edits") {
  const Registry& reg = Registry::instance();
  CHECK(reg.closest("ATL") == "ALT");
  CHECK(reg.closest("hdgg") == "HDG");
  CHECK(reg.closest("CRECONFSS") == "CRECONFS");
  CHECK(reg.closest("XYZZY") == "");
  CHECK(reg.closest("KL204") == "");
}

TEST_CASE("bluesky_only: display and plugin commands and zoom keys, nothing else") {
  CHECK(bluesky_only("PAN"));
  CHECK(bluesky_only("zoom"));
  CHECK(bluesky_only("SWRAD"));
  CHECK(bluesky_only("TRAFGEN"));
  CHECK(bluesky_only("+++"));
  CHECK(bluesky_only("--"));
  CHECK_FALSE(bluesky_only("ATL"));
  CHECK_FALSE(bluesky_only("+-"));
  CHECK_FALSE(bluesky_only(""));
}

TEST_CASE("a .scn typo fails at file:line naming the closest command; PAN is skipped") {
  const fs::path d = fs::temp_directory_path() / "squawk_unknown_command";
  fs::create_directories(d);
  const std::string path = (d / "typo.scn").string();
  REQUIRE(files::write_atomic(path,
                              "# line 1\n"
                              "00:00:00.00>CRE KL204 B744 52 4 90 FL200 250\n"
                              "00:00:00.00>PAN KL204\n"
                              "00:00:05.00>ATL KL204 FL300\n"
                              "00:00:06.00>SCHEDULE 10 KL204 ALT FL9X\n"));
  Stack s(1);
  REQUIRE(s.load_scenario(path));
  REQUIRE(s.run_until(20.0));
  CHECK(s.tally().skipped.at("PAN") == 1);
  CHECK(s.tally().skipped.count("ATL") == 0);
  REQUIRE(s.tally().first_failures.size() == 2);
  CHECK(s.tally().first_failures[0] == "t=5 s: " + path +
                                           ":4: ATL KL204 FL300: unknown command or aircraft 'ATL' - did you mean "
                                           "ALT? (`HELP` lists the commands)");
  CHECK(s.tally().first_failures[1].rfind("t=10 s: " + path + ":5: KL204 ALT FL9X: ", 0) == 0);
  // A typed command has no file: the failure is the message alone.
  auto typed = s.exec("ATL KL204 FL100");
  REQUIRE_FALSE(typed);
  CHECK(typed.status().message().find("did you mean ALT?") != std::string::npos);
  fs::remove_all(d);
}
