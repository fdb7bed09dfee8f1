// Property: a random mix of valid and invalid commands; after every failed
// command the full state (Simulation::snapshot() + the stack's own state) is
// byte for byte what it was before. Also: a line check() rejects, exec()
// rejects too.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "command/stack.h"
#include "core/rng.h"

using namespace squawk;
using namespace squawk::command;

namespace {

struct Gen {
  Rng rng{2024};
  std::vector<std::string> ids{"KL204", "AF1", "BA22", "LH400"};

  template <size_t N>
  std::string pick(const char* const (&opts)[N]) { return opts[rng.uniform_int(0, N - 1)]; }

  std::string acid() {
    static const char* const kBad[] = {"NOPE", "*", "", "kl204"};
    return rng.uniform() < 0.8 ? ids[rng.uniform_int(0, ids.size() - 1)] : pick(kBad);
  }
  std::string alt() {
    static const char* const k[] = {"FL100", "FL350", "5000", "0", "fl050", "FL9X", "abc", "-99999", "FL", ","};
    return pick(k);
  }
  std::string spd() {
    static const char* const k[] = {"250", "M.78", ".8", "0.78", "M78", "300", "fast", "-5", "M3", "5000"};
    return pick(k);
  }
  std::string hdg() {
    static const char* const k[] = {"90", "270", "-10", "236.9T", "M045", "720", "west", "1e999", "T"};
    return pick(k);
  }
  std::string lat() {
    static const char* const k[] = {"52", "52.3", "N52'10'00", "S1", "91", "north", "-45.5"};
    return pick(k);
  }
  std::string lon() {
    static const char* const k[] = {"4", "4.5", "E004'30'", "W2", "400", "east", "-120"};
    return pick(k);
  }
  std::string wpt() {
    static const char* const k[] = {"ALPHA", "BRAVO", "NOWHERE", "*", "KL204001"};
    return pick(k);
  }
  std::string time() {
    static const char* const k[] = {"10", "0:30", "00:01:00", "soon", "1:2:3:4", "-5"};
    return pick(k);
  }
  std::string vs() {
    static const char* const k[] = {"1500", "-800", "0", "up"};
    return pick(k);
  }

  std::string command() {
    switch (rng.uniform_int(0, 39)) {
      case 39:
        return "NEAR " + lat() + " " + lon() + " " + command();
      case 34:
      case 35:
      case 36:
      case 37:
      case 38:
        return "CRE X" + std::to_string(rng.uniform_int(0, 999)) + " A320 " + std::to_string(rng.uniform(51, 53)) +
               " " + std::to_string(rng.uniform(3, 5)) + " " + std::to_string(rng.uniform_int(0, 359)) + " FL" +
               std::to_string(rng.uniform_int(50, 350)) + " " + std::to_string(rng.uniform_int(200, 320));
      case 0: {
        const std::string id = rng.uniform() < 0.5 ? ids[rng.uniform_int(0, ids.size() - 1)] : "X" + std::to_string(rng.uniform_int(0, 99));
        return "CRE " + id + " B744 " + lat() + " " + lon() + " " + hdg() + " " + alt() + " " + spd();
      }
      case 1: return "ALT " + acid() + " " + alt() + (rng.uniform() < 0.3 ? " " + vs() : "");
      case 2: return acid() + " HDG " + hdg();
      case 3: return "SPD " + acid() + "," + spd();
      case 4: return "VS " + acid() + " " + vs();
      case 5: return "BANK " + acid() + " " + std::to_string(rng.uniform_int(-10, 100));
      case 6: return "MOVE " + acid() + " " + lat() + " " + lon() + " " + alt();
      case 7: return rng.uniform() < 0.3 ? "DEL " + acid() : "POS " + acid();
      case 8: return "ADDWPT " + acid() + " " + (rng.uniform() < 0.5 ? wpt() : lat() + " " + lon()) + " " + alt() + " " + spd();
      case 9: return "DEFWPT " + wpt() + " " + lat() + " " + lon();
      case 10: return "DIRECT " + acid() + " " + wpt();
      case 11: return "DELWPT " + acid() + " " + wpt();
      case 12: return "LNAV " + acid() + " " + (rng.uniform() < 0.5 ? "ON" : "OFF");
      case 13: return "VNAV " + acid() + " " + (rng.uniform() < 0.5 ? "ON" : "maybe");
      case 14: return acid() + " ATALT " + alt() + " " + acid() + " ALT " + alt();
      case 15: return "SCHEDULE " + time() + " " + acid() + " SPD " + spd();
      case 16: return "DELAY " + time() + " ECHO hello";
      case 17: return "DT " + std::string(rng.uniform() < 0.5 ? "0.1" : "-1");
      case 18: return "ZONER " + std::string(rng.uniform() < 0.5 ? "3" : "-3");
      case 19: return "RESO " + std::string(rng.uniform() < 0.5 ? "MVP" : "SSD");
      case 20: return "ASAS " + std::string(rng.uniform() < 0.5 ? "ON" : "MAYBE");
      case 21: return "CRECONFS I" + std::to_string(rng.uniform_int(0, 20)) + " A320 " + acid() + " " + hdg() + " " + std::to_string(rng.uniform_int(-1, 4)) + " " + time();
      case 22: return acid() + " AT " + wpt() + " ALT " + alt();
      case 23: return acid() + " AFTER " + wpt() + " ADDWPT " + wpt();
      case 24: return "DEST " + acid() + " " + wpt();
      case 25: return "MCRE " + std::to_string(rng.uniform_int(-1, 3)) + " * " + alt();
      case 26: return "SEED " + std::to_string(rng.uniform_int(-1, 9));
      case 27: return "FF " + time();
      case 28: return rng.uniform() < 0.5 ? "HOLD" : "OP";
      case 29: return "LISTRTE " + acid() + " " + std::to_string(rng.uniform_int(0, 3));
      case 30: return "DTLOOK " + time();
      case 31: return acid() + " ATDIST " + lat() + " " + lon() + " " + std::to_string(rng.uniform_int(-1, 20)) + " ECHO near";
      case 32: return "RFACH " + std::string(rng.uniform() < 0.5 ? "1.2" : "0.5");
      case 33: {
        static const char* const junk[] = {"", ";", "FROB", "CRE", "ALT", "KL204 KL204", "'unterminated", ",,,", "DEL * *"};
        return pick(junk);
      }
      default:
        return "ECHO unreachable";
    }
  }
};

}  // namespace

TEST_CASE("property: failed commands leave the full state byte-identical") {
  Gen g;
  Stack s(5);
  REQUIRE(s.exec("CRE KL204 B744 52 4 90 FL200 250; CRE AF1 A320 52.1 4.1 270 FL210 260"));
  int failed = 0, ok = 0, check_disagree = 0, changed_on_failure = 0;
  for (int n = 0; n < 4000; ++n) {
    const std::string line = g.command();
    const std::string before = s.snapshot();
    const bool parses = s.check(line).is_ok();
    auto r = s.exec(line);
    if (r) {
      ++ok;
    } else {
      ++failed;
      if (s.snapshot() != before && ++changed_on_failure <= 5) MESSAGE("state changed by failed: " << line);
    }
    if (!parses && r && ++check_disagree <= 5) MESSAGE("check() rejected but exec() accepted: " << line);
    if (n % 50 == 49) REQUIRE(s.run_until(s.sim().simt() + 7.0));
  }
  MESSAGE(ok << " commands succeeded, " << failed << " failed; " << s.sim().n() << " aircraft at the end");
  CHECK(changed_on_failure == 0);
  CHECK(check_disagree == 0);
  CHECK(ok > 800);
  CHECK(failed > 800);
}
