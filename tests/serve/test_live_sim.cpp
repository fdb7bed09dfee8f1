// JSON views of the simulation and the live owner thread of `squawk serve`.
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>

#include "script/serve_session.h"
#include "serve/live_sim.h"
#include "serve/state_json.h"

using namespace squawk;
using nlohmann::json;

TEST_CASE(
    "state_json: aircraft with selected values and route; each conflict once, own before intruder, "
    "CPA points") {
  command::Stack s;
  for (const char* line : {"ASAS ON", "CRE KL204 B744 52 4 90 FL200 280", "CRE AF123 A320 52 4.6 270 FL200 280",
                           "DEFWPT EXIT1 52.0 5.0", "KL204 ADDWPT EXIT1 FL240", 
                           "CRE BAW1 A320 50 0 0 FL100 250", "ALT BAW1 FL300", "HDG BAW1 10"})
    REQUIRE(s.exec(line).is_ok());
  REQUIRE(s.run_until(2.0).is_ok());
  const json j = serve::state_json(s);
  CHECK(j["simt"].get<double>() == doctest::Approx(2.0));
  REQUIRE(j["aircraft"].size() == 3);
  const json& kl = j["aircraft"][0];
  CHECK(kl["id"] == "KL204");
  CHECK(kl["sel_alt_ft"].get<double>() == doctest::Approx(20000.0));
  CHECK(kl["route"].size() == 1);
  CHECK(kl["route"][0]["name"] == "EXIT1");
  CHECK(kl["route"][0]["alt_ft"].get<double>() == doctest::Approx(24000.0).epsilon(1e-6));
  CHECK(kl["active_wpt"] == "EXIT1");
  const json& af = j["aircraft"][1];
  CHECK(j["aircraft"][2]["sel_alt_ft"].get<double>() == doctest::Approx(30000.0));
  CHECK(j["aircraft"][2]["vs_fpm"].get<double>() > 0);
  CHECK(j["aircraft"][2]["sel_hdg_deg"].get<double>() == doctest::Approx(10.0));
  CHECK(af["sel_cas_kt"].get<double>() == doctest::Approx(280.0).epsilon(1e-6));
  CHECK(af["route"].empty());
  CHECK(af["active_wpt"].is_null());
  CHECK(j["trail"] == json({{"on", false}, {"dt_s", 10.0}, {"colour", json::object()}}));
  REQUIRE(s.exec("TRAIL ON 4; TRAIL KL204 YELLOW").is_ok());
  CHECK(serve::state_json(s)["trail"] == json({{"on", true}, {"dt_s", 4.0}, {"colour", {{"KL204", "YELLOW"}}}}));

  // The detector reports the pair in both orders; the view once, a < b.
  REQUIRE(s.sim().conflicts().size() == 2);
  REQUIRE(j["conflicts"].size() == 1);
  const json& c = j["conflicts"][0];
  CHECK((c["own"] == "AF123" && c["intruder"] == "KL204"));
  CHECK(c["tcpa_s"].get<double>() > 0);
  CHECK(c["tlos_s"].get<double>() < c["tcpa_s"].get<double>());
  // The CPA points lie about dcpa apart (flat earth, 1 deg lat = 60 NM; the
  // detector ran up to asas_dt = 1 s before the present state).
  const double dlat = (c["cpa"][0][0].get<double>() - c["cpa"][1][0].get<double>()) * 60;
  const double dlon = (c["cpa"][0][1].get<double>() - c["cpa"][1][1].get<double>()) * 60 * std::cos(52 * M_PI / 180);
  CHECK(std::fabs(std::hypot(dlat, dlon) - c["dcpa_nm"].get<double>()) < 0.05);
  // ... and on KL204's track (east along 52 N) about tcpa ahead.
  const double run_nm = (c["cpa"][1][1].get<double>() - kl["lon"].get<double>()) * 60 * std::cos(52 * M_PI / 180);
  CHECK(run_nm == doctest::Approx(kl["gs_kt"].get<double>() * c["tcpa_s"].get<double>() / 3600).epsilon(0.02));
}

TEST_CASE("navdata_json: points inside the box, at most `limit`") {
  command::NavDb db({{"EHAM", "APT", 52.3, 4.76}, {"EGLL", "APT", 51.47, -0.45}},
                    {{"SPY", "VOR", 52.54, 4.85}, {"ARTIP", "FIX", 52.51, 5.57}, {"LAM", "VOR", 51.65, 0.15}});
  const json all = serve::navdata_json(&db, {50, 54, 3, 6}, 100);
  CHECK(all["airports"] == json::array({json::array({"EHAM", 52.3, 4.76})}));
  CHECK(all["navaids"] == json::array({json::array({"SPY", 52.54, 4.85, "VOR"})}));
  CHECK(all["fixes"] == json::array({json::array({"ARTIP", 52.51, 5.57})}));
  CHECK(all["truncated"] == false);
  const json two = serve::navdata_json(&db, {50, 54, 3, 6}, 2);
  CHECK(two["airports"].size() + two["navaids"].size() + two["fixes"].size() == 2);
  CHECK(two["truncated"] == true);
  CHECK(serve::navdata_json(nullptr, {}, 10)["fixes"].empty());
  const json apts = serve::navdata_json(&db, {50, 54, 3, 6}, 100, {true, false, false});
  CHECK(apts["airports"].size() == 1);
  CHECK((apts["navaids"].empty() && apts["fixes"].empty()));
}

TEST_CASE("LiveSim: requests run on the owner thread; the state is published after each") {
  script::Vm vm({});
  auto session = script::ServeSession::open(vm, "", "offline");
  REQUIRE(session.is_ok());
  serve::LiveSim live(**session, {});
  live.start();
  const auto timeout = std::chrono::seconds(30);
  auto r = live.call([](serve::LiveSim& l) { return l.command("!CRE KL204 B744 52 4 90 FL200 280", "controller"); },
                     timeout);
  REQUIRE(r.is_ok());
  CHECK((*r)["ok"] == true);
  json st = json::parse(*live.state().second);
  REQUIRE(st["aircraft"].size() == 1);
  CHECK(st["log"].back()["who"] == "controller");

  r = live.call([](serve::LiveSim& l) { return l.command("KL204 turn left heading 270", "controller"); }, timeout);
  REQUIRE(r.is_ok());
  CHECK((*r)["commands"] == json::array({"HDG KL204 270 LEFT"}));
  st = json::parse(*live.state().second);
  CHECK(st["aircraft"][0]["sel_hdg_deg"].get<double>() == doctest::Approx(270.0));
  CHECK(st["aircraft"][0]["sel_turn"] == "LEFT");  // the commanded way, until the heading is captured

  // A failing command reports the culprit and changes nothing.
  r = live.call([](serve::LiveSim& l) { return l.command("!ALT KL204 FL9X", "controller"); }, timeout);
  REQUIRE(r.is_ok());
  CHECK((*r)["ok"] == false);
  CHECK((*r)["message"].get<std::string>().find("FL9X") != std::string::npos);
  CHECK(json::parse(*live.state().second)["aircraft"][0]["sel_alt_ft"].get<double>() == doctest::Approx(20000.0));

  // No advisory without a teammate; decisions on unknown ones are refused.
  r = live.call([](serve::LiveSim& l) { return l.decide(1, true, "controller"); }, timeout);
  REQUIRE(r.is_ok());
  CHECK((*r)["ok"] == false);
  live.stop();
  auto late = live.call([](serve::LiveSim&) { return json(); }, timeout);
  CHECK(late.status().code() == Code::kUnavailable);
}

TEST_CASE("LiveSim: of a full log the simulation's entries go first, the decisions stay") {
  script::Vm vm({});
  auto session = script::ServeSession::open(vm, "", "offline");
  REQUIRE(session.is_ok());
  serve::LiveOptions lo;
  lo.log_shown = 5;
  serve::LiveSim live(**session, lo);
  live.start();
  auto r = live.call(
      [](serve::LiveSim& l) {
        l.log("controller", "accepted advisory 1");
        l.log("auto", "automatic execution of advisories on");
        for (int i = 0; i < 10; ++i) l.log("sim", "conflict " + std::to_string(i));
        return json{{"ok", true}};
      },
      std::chrono::seconds(30));
  REQUIRE(r.is_ok());
  const json log = json::parse(*live.state().second)["log"];
  REQUIRE(log.size() == 5);
  CHECK(log[0]["text"] == "accepted advisory 1");
  CHECK(log[1]["who"] == "auto");
  CHECK(log[4]["text"] == "conflict 9");
}
