#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/text.h"
#include "viz/chart.h"
#include "viz/csv.h"
#include "viz/layout.h"
#include "viz/scene.h"
#include "viz/traffic_scene.h"

using namespace squawk;

namespace {
size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("nice ticks are 1-2-5 steps inside the range") {
  CHECK(viz::nice_ticks(0, 1, 5) == std::vector<double>{0, 0.2, 0.4, 0.6000000000000001, 0.8, 1});
  // Range 2.9 over 5 ticks: raw step 0.58 rounds up to 1; ticks lie inside the range.
  CHECK(viz::nice_ticks(-2.3, 0.6, 5) == std::vector<double>{-2, -1, 0});
  CHECK(viz::nice_ticks(-2.3, 0.6, 10) == std::vector<double>{-2, -1.5, -1, -0.5, 0, 0.5});
  CHECK(viz::nice_ticks(0, 100000, 5)[1] == 20000);
  CHECK(!viz::nice_ticks(3, 3).empty());  // degenerate range still gets ticks
}

TEST_CASE("CSV: header, NaN for non-numbers, ragged lines are errors") {
  auto t = viz::parse_csv("episodes,success_rate,mean_reward\n100,0.5,-2\n200,x,-1\n");
  REQUIRE(t.is_ok());
  CHECK(t->columns.size() == 3);
  CHECK(t->column("mean_reward") == 2);
  CHECK(t->column("nope") == -1);
  CHECK(std::isnan(t->rows[1][1]));
  auto bad = viz::parse_csv("a,b\n1,2\n3\n");
  REQUIRE(!bad.is_ok());
  CHECK(bad.status().message().find("line 3 has 1 cells") != std::string::npos);
}

namespace {
// Two interleaved episodes as env::JsonlRecorder writes them.
const char* kRecording =
    R"({"event":"reset","episode":0,"rules":"paper","t":0,"waypoint":[53.1,4.0],"own":[52.0,4.0,0,150],"intruders":[[52.5,4.1,200,150],[52.3,3.8,90,150]]})" "\n"
    R"({"event":"reset","episode":1,"rules":"paper","t":0,"waypoint":[53.0,4.0],"own":[52.0,4.0,0,150],"intruders":[[52.9,4.1,180,150],[52.3,3.9,90,150]]})" "\n"
    R"({"event":"step","episode":0,"t":50,"agent":true,"action":0.5,"hdg_cmd":10,"reward":0.02,"intrusions":0,"own":[52.04,4.0,10,150],"intruders":[[52.05,4.01,200,150],[52.3,3.85,90,150]],"note":"KL001, turn right heading 010"})" "\n"
    R"({"event":"step","episode":1,"t":50,"agent":false,"hdg_cmd":0,"reward":0,"intrusions":0,"own":[52.04,4.0,0,150],"intruders":[[52.85,4.1,180,150],[52.3,3.95,90,150]]})" "\n"
    R"({"event":"end","episode":0,"return":0.02,"success":true,"reached":true,"truncated":false,"steps":1,"decisions":1,"intrusions":0,"t":50})" "\n";
}  // namespace

TEST_CASE("recorded episodes are read per episode and rendered") {
  auto first = viz::parse_episode_jsonl(kRecording);
  REQUIRE(first.is_ok());
  CHECK(first->frames.size() == 2);
  CHECK(first->wpt_lat == 53.1);
  CHECK(first->frames[1].aircraft[0].id == "KL001");
  CHECK(first->frames[1].aircraft[1].id == "0");
  CHECK(first->frames[1].note == "KL001, turn right heading 010");
  auto second = viz::parse_episode_jsonl(kRecording, 1);
  REQUIRE(second.is_ok());
  CHECK(second->wpt_lat == 53.0);
  CHECK(second->frames[1].aircraft[1].lat == 52.85);
  CHECK(viz::parse_episode_jsonl(kRecording, 7).status().message().find("no episode 7") != std::string::npos);

  const std::string svg = viz::render_scene(*first);
  CHECK(svg.rfind("<?xml", 0) == 0);
  // One separation circle per intruder, two waypoint circles, two closest-approach dots.
  CHECK(count(svg, "<circle") == 6);
  // Intruder 0 came within 0.7 NM of the ownship at t = 50 s, and it says so.
  CHECK(svg.find(">closest 0.7 NM</text>") != std::string::npos);
  CHECK(svg.find(">to 0, t = 50 s</text>") != std::string::npos);
  // Caption on two lines, parts separated so that SVG cannot run them together.
  CHECK(svg.find(">episode 0 (paper rules)</text>") != std::string::npos);
  CHECK(svg.find(">t = 50 s \u00b7 frame 1/1 \u00b7 circles: 5 NM separation</text>") != std::string::npos);
  // Intruder 0 is 0.6 NM from the ownship in the last frame: its circle is red.
  CHECK(count(svg, "stroke=\"#dc143c\"") >= 1);
  CHECK(svg.find(">N</text>") != std::string::npos);
  CHECK(svg.find(" km</text>") != std::string::npos);
  CHECK(svg.find("KL001, turn right heading 010") != std::string::npos);
}

TEST_CASE("recording errors name the line") {
  auto e = viz::parse_episode_jsonl(std::string(kRecording) + "not json\n");
  REQUIRE(!e.is_ok());
  CHECK(e.status().message().find("episode line 6") != std::string::npos);
  e = viz::parse_episode_jsonl(R"({"event":"step","episode":0,"t":0,"own":[1,2,3,4],"intruders":[]})" "\n", 0);
  CHECK(e.status().message().find("before its reset") != std::string::npos);
  e = viz::parse_episode_jsonl(R"({"event":"reset","episode":0})" "\n");
  CHECK(e.status().message().find("expected a recorder event") != std::string::npos);
}

TEST_CASE("axes: padded, ending on labelled ticks; x from 0") {
  const viz::Axis a = viz::axis(-1.27, 0.04, 0.04, 5);
  CHECK(a.lo < -1.27);
  CHECK(a.hi > 0.04);
  CHECK(a.ticks.front() == doctest::Approx(a.lo));
  CHECK(a.ticks.back() == doctest::Approx(a.hi));  // the top tick exists, so it is labelled
  viz::Panel p{"reward", "episodes", "reward", {}, false, 0, 0};
  p.series.push_back({"run", {5000, 100000, 200000}, {-1.27, -0.1, 0.04}, "#1f77b4"});
  const std::string svg = viz::panels_svg({p});
  CHECK(svg.find(">0</text>") != std::string::npos);         // x starts at 0
  CHECK(svg.find(">" + text::fmt_double(a.hi, 3) + "</text>") != std::string::npos);
}

TEST_CASE("panels draw every series") {
  viz::Panel p{"Average success rate", "episodes", "success", {}, true, 0, 1};
  p.series.push_back({"mlp", {0, 1000, 2000}, {0.6, 0.8, 0.95}, "#1f77b4"});
  const std::string svg = viz::panels_svg({p, p});
  CHECK(count(svg, "<polyline") == 2);
  CHECK(count(svg, "Average success rate") == 2);
}

TEST_CASE("frames outside the episode are errors that give the range") {
  auto sc = viz::parse_episode_jsonl(kRecording);
  REQUIRE(sc.is_ok());
  CHECK(viz::check_frame(*sc, -1).is_ok());
  CHECK(viz::check_frame(*sc, 0).is_ok());
  CHECK(viz::check_frame(*sc, 1).is_ok());
  for (long long bad : {2LL, 999LL, -3LL}) {
    const Status st = viz::check_frame(*sc, bad);
    REQUIRE(!st.is_ok());
    CHECK(st.message().find("numbered 0 to 1") != std::string::npos);
  }
}

TEST_CASE("texts fit the picture: shrunk, then cut") {
  std::string s = "short";
  CHECK(viz::fit_text(s, 200, 12, 7) == 12);
  CHECK(s == "short");
  s = std::string(60, 'x');  // 60 * 0.62 * 12 = 446 px at 12 px
  const double f = viz::fit_text(s, 300, 12, 7);
  CHECK(f < 12);
  CHECK(f >= 7);
  CHECK(viz::text_width(s, f) <= 300);
  s = std::string(200, 'x');
  CHECK(viz::fit_text(s, 300, 12, 7) == 7);
  CHECK(s.size() < 200);
  CHECK(s.substr(s.size() - 3) == "...");
  CHECK(viz::text_width(s, 7) <= 300);

  // A 400 px picture with a long title: every caption text fits the width.
  auto sc = viz::parse_episode_jsonl(kRecording);
  REQUIRE(sc.is_ok());
  sc->title = "a very long title that would run past the right edge of a small picture, episode 0";
  const std::string svg = viz::render_scene(*sc, {400, -1});
  CHECK(svg.find("...</text>") != std::string::npos);
}

TEST_CASE("labels avoid obstacles and each other") {
  viz::LabelLayout layout({0, 0, 400, 400});
  layout.block({195, 195, 205, 205});  // a symbol at the anchor
  layout.block({210, 180, 300, 220});  // something to the right
  const auto a = layout.place({200, 200}, 40, 12, 8);
  REQUIRE(a);
  const viz::Box ba{a->x, a->y, a->x + 40, a->y + 12};
  CHECK(!ba.overlaps({195, 195, 205, 205}));
  CHECK(!ba.overlaps({210, 180, 300, 220}));
  const auto b = layout.place({200, 200}, 40, 12, 8);
  REQUIRE(b);
  CHECK(!viz::Box{b->x, b->y, b->x + 40, b->y + 12}.overlaps(ba));
  // Boxed in on every side: an optional label is left out, a required one placed.
  viz::LabelLayout full({0, 0, 100, 100});
  full.block({0, 0, 100, 100});
  CHECK(!full.place({50, 50}, 10, 10, 5, false));
  CHECK(full.place({50, 50}, 10, 10, 5, true));
}

TEST_CASE("a scenario's traffic as a scene: samples, labels, conflicts") {
  command::Stack stack;
  REQUIRE(stack.exec("CRE BAW1 B744 52 4 90 FL300 280").is_ok());
  REQUIRE(stack.exec("CRE DLH2 A320 52 4.8 270 FL300 280").is_ok());
  REQUIRE(stack.exec("ASAS ON").is_ok());
  auto sc = viz::traffic_scene(stack, 60, 4);
  REQUIRE(sc.is_ok());
  CHECK(!sc->ownship);
  CHECK(!sc->waypoint);
  REQUIRE(sc->frames.size() == 4);
  CHECK(sc->frames[0].t == 0);
  CHECK(sc->frames[3].t == doctest::Approx(60));
  CHECK(stack.sim().simt() == doctest::Approx(60));
  const auto& last = sc->frames[3].aircraft;
  REQUIRE(last.size() == 2);
  CHECK(last[0].info == "FL300 280 kt");
  CHECK(last[0].alert);  // head-on, the detector sees the conflict
  CHECK(!sc->frames[0].aircraft[0].alert);  // no detection has run at t = 0
  const std::string svg = viz::render_scene(*sc);
  CHECK(svg.find(">BAW1</text>") != std::string::npos);
  CHECK(svg.find(">FL300 280 kt</text>") != std::string::npos);
  CHECK(count(svg, "stroke=\"#dc143c\"") == 2);  // both protected zones red
  CHECK(!viz::traffic_scene(stack, 30).is_ok());  // before now
}
