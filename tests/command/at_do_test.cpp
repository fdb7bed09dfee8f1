// AT acid wp DO command (BlueSky's route.py Route.at / runactwpstack): the
// stored commands run once when the waypoint is passed, at the step after the
// switch, in the order given; they go with a deleted waypoint; a bad AT DO
// fails at once, names the culprit and leaves the state as it was.
#include <doctest/doctest.h>

#include <filesystem>

#include "command/stack.h"
#include "core/files.h"
#include "core/units.h"
#include "failed_exec.h"

using namespace squawk;
using namespace squawk::command;
using squawk::test::error_of;
namespace fs = std::filesystem;

namespace {

// KL204 at 52N 4E flying east at FL200, 250 kt, with a route ALPHA (11 NM
// ahead) then BRAVO.
Stack eastbound() {
  Stack s(1);
  for (const char* line : {"CRE KL204 B744 52.0 4.0 90 FL200 250", "DEFWPT ALPHA 52.0 4.3",
                           "DEFWPT BRAVO 52.0 4.8", "ADDWPT KL204 ALPHA", "ADDWPT KL204 BRAVO"})
    REQUIRE_MESSAGE(s.exec(line), line);
  return s;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Steps until the active waypoint leaves index 0; returns the time [s] of that step.
double step_past_first(Stack& s) {
  while (s.sim().traffic().route[0].active() == 0 && s.sim().simt() < 600.0) s.step();
  REQUIRE(s.sim().traffic().route[0].active() == 1);
  return s.sim().simt();
}

}  // namespace

TEST_CASE("AT DO: the command runs once, at the step after the waypoint is passed, not before") {
  Stack s = eastbound();
  const auto& t = s.sim().traffic();
  REQUIRE(s.exec("AT KL204 ALPHA DO ALT KL204 FL80"));
  CHECK(t.route[0].waypoints()[0].commands == std::vector<std::string>{"ALT KL204 FL80"});
  const double fl200 = units::ft_to_m(20000.0), fl80 = units::ft_to_m(8000.0);
  const double passed = step_past_first(s);
  CHECK(passed > 60.0);                           // 11 NM at about 330 kt TAS
  CHECK(t.sel_alt[0] == doctest::Approx(fl200));  // not yet: it runs at the next step
  s.step();
  CHECK(t.sel_alt[0] == doctest::Approx(fl80));
  // once: a new clearance after the passage is not overwritten by the stored one
  REQUIRE(s.exec("ALT KL204 FL150"));
  REQUIRE(s.run_until(s.sim().simt() + 60.0));
  CHECK(t.sel_alt[0] == doctest::Approx(units::ft_to_m(15000.0)));
  CHECK(s.take_output().empty());
}

TEST_CASE(
    "AT DO: several commands run in the order given; the aircraft's id is put first where "
    "missing") {
  Stack s = eastbound();
  REQUIRE(s.exec("KL204 AT ALPHA DO ECHO one"));
  REQUIRE(s.exec("KL204 AT ALPHA STACK SPD 200"));
  REQUIRE(s.exec("KL204 AT ALPHA DO ECHO two"));
  REQUIRE(s.exec("KL204 AT ALPHA ALT FL150"));  // a constraint keeps the commands
  auto shown = s.exec("KL204 AT ALPHA");
  REQUIRE(shown);
  CHECK(*shown == "KL204 at ALPHA: FL150/---\nStack:\nECHO one\nKL204 SPD 200\nECHO two");
  CHECK(*s.exec("KL204 AT BRAVO") == "KL204 at BRAVO: -----/---");
  step_past_first(s);
  CHECK(s.take_output().empty());
  s.step();
  CHECK(s.take_output() == std::vector<std::string>{"one", "two"});
  CHECK(s.sim().traffic().sel_spd[0] == doctest::Approx(units::kt_to_ms(200.0)));
}

TEST_CASE("AT DO: the commands go with a deleted waypoint") {
  Stack s = eastbound();
  REQUIRE(s.exec("AT KL204 ALPHA DO ECHO at alpha"));
  REQUIRE(s.exec("AT KL204 BRAVO DO ECHO at bravo"));
  REQUIRE(s.exec("DELWPT KL204 ALPHA"));
  const auto& r = s.sim().traffic().route[0];
  REQUIRE(r.size() == 1);
  CHECK(r.waypoints()[0].commands == std::vector<std::string>{"ECHO at bravo"});
  REQUIRE(s.run_until(90.0));  // past where ALPHA was
  CHECK(s.take_output().empty());
}

TEST_CASE(
    "AT DO: a bad command fails when AT is given, naming it and the waypoint; state unchanged") {
  Stack s = eastbound();
  const std::string unknown = error_of(s, "AT KL204 ALPHA DO ALTT KL204 FL80");
  CHECK(has(unknown, "ALPHA"));
  CHECK(has(unknown, "'ALTT'"));
  CHECK(has(error_of(s, "AT KL204 ALPHA DO ALT KL204 banana"), "ALPHA"));
  CHECK(has(error_of(s, "AT KL204 ALPHA DO ALT XX999 FL80"), "XX999"));
  CHECK(has(error_of(s, "AT KL204 ALPHA DO"), "missing"));
  const std::string off_route = error_of(s, "AT KL204 CHARLIE DO ALT KL204 FL80");
  CHECK(has(off_route, "'CHARLIE' is not in the route of KL204"));
  CHECK(s.sim().traffic().route[0].waypoints()[0].commands.empty());
}

TEST_CASE("AT DO: the stored commands are state (snapshot) and copy with the stack") {
  Stack s = eastbound();
  const std::string before = s.snapshot();
  REQUIRE(s.exec("AT KL204 ALPHA DO ALT KL204 FL80"));
  CHECK(s.snapshot() != before);
  Stack copy = s;
  CHECK(copy.snapshot() == s.snapshot());
}

TEST_CASE("AT DO from a .scn line") {
  fs::path d = fs::temp_directory_path() / "squawk_command_at_do";
  fs::remove_all(d);
  fs::create_directories(d);
  REQUIRE(files::write_atomic((d / "atdo.scn").string(),
                              "00:00:00.00>CRE KL204 B744 52.0 4.0 90 FL200 250\n"
                              "00:00:00.00>DEFWPT ALPHA 52.0 4.3\n"
                              "00:00:00.00>ADDWPT KL204 ALPHA\n"
                              "00:00:00.00>ADDWPT KL204 52.0 4.8\n"
                              "00:00:00.00>KL204 AT ALPHA DO ALT FL80\n"));
  Stack s(1);
  s.set_base_dir(d.string());
  REQUIRE(s.exec("IC atdo"));
  REQUIRE(s.run_until(1.0));
  const auto& t = s.sim().traffic();
  REQUIRE(t.n() == 1);
  CHECK(t.route[0].waypoints()[0].commands == std::vector<std::string>{"KL204 ALT FL80"});
  REQUIRE(s.run_until(30.0));
  CHECK(t.sel_alt[0] == doctest::Approx(units::ft_to_m(20000.0)));
  REQUIRE(s.run_until(200.0));
  CHECK(t.sel_alt[0] == doctest::Approx(units::ft_to_m(8000.0)));
  CHECK(s.tally().failed.empty());
}
