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

TEST_CASE("episode JSONL round trip and rendering") {
  viz::Scene s;
  s.title = "demo";
  s.wpt_lat = 53.1;
  s.wpt_lon = 4.0;
  viz::Frame f0{0, {{"KL001", 52.0, 4.0, 0}, {"I1", 52.5, 4.1, 200}, {"I2", 52.3, 3.8, 90}}, ""};
  viz::Frame f1{50, {{"KL001", 52.04, 4.0, 10}, {"I1", 52.05, 4.01, 200}, {"I2", 52.3, 3.85, 90}},
                "KL001, turn right heading 010"};
  std::string text = viz::to_jsonl_header(s) + viz::to_jsonl_frame(f0, 0, false) +
                     viz::to_jsonl_frame(f1, 0.5, true);
  auto back = viz::parse_episode_jsonl(text);
  REQUIRE(back.is_ok());
  CHECK(back->frames.size() == 2);
  CHECK(back->frames[1].aircraft[1].id == "I1");
  CHECK(back->frames[1].note == "KL001, turn right heading 010");
  const std::string svg = viz::render_scene(*back);
  CHECK(svg.rfind("<?xml", 0) == 0);
  // One separation circle per intruder plus two waypoint circles.
  CHECK(count(svg, "<circle") == 4);
  // I1 is 0.6 NM from the ownship in the last frame: its circle is red.
  CHECK(count(svg, "stroke=\"#dc143c\"") >= 1);
  CHECK(svg.find(">N</text>") != std::string::npos);
  CHECK(svg.find(" km</text>") != std::string::npos);
  CHECK(svg.find("KL001, turn right heading 010") != std::string::npos);
}

TEST_CASE("episode JSONL errors name the line") {
  auto e = viz::parse_episode_jsonl("{\"episode\": {\"waypoint\": {\"lat\": 1, \"lon\": 2}}}\nnot json\n");
  REQUIRE(!e.is_ok());
  CHECK(e.status().message().find("episode line 2") != std::string::npos);
  e = viz::parse_episode_jsonl("{\"t\": 0, \"aircraft\": [{\"id\": \"A\", \"lat\": 1, \"lon\": 2}]}\n");
  CHECK(e.status().message().find("header") != std::string::npos);
  e = viz::parse_episode_jsonl("{\"episode\": {}}\n");
  CHECK(e.status().message().find("waypoint") != std::string::npos);
}

TEST_CASE("panels draw every series") {
  viz::Panel p{"Average success rate", "episodes", "success", {}, true, 0, 1};
  p.series.push_back({"mlp", {0, 1000, 2000}, {0.6, 0.8, 0.95}, "#1f77b4"});
  const std::string svg = viz::panels_svg({p, p});
  CHECK(count(svg, "<polyline") == 2);
  CHECK(count(svg, "Average success rate") == 2);
}
