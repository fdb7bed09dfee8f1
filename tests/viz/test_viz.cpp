#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "viz/chart.h"
#include "viz/csv.h"
#include "viz/scene.h"

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
  // One separation circle per intruder plus two waypoint circles.
  CHECK(count(svg, "<circle") == 4);
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

TEST_CASE("panels draw every series") {
  viz::Panel p{"Average success rate", "episodes", "success", {}, true, 0, 1};
  p.series.push_back({"mlp", {0, 1000, 2000}, {0.6, 0.8, 0.95}, "#1f77b4"});
  const std::string svg = viz::panels_svg({p, p});
  CHECK(count(svg, "<polyline") == 2);
  CHECK(count(svg, "Average success rate") == 2);
}
