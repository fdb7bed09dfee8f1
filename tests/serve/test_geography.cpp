#include <doctest/doctest.h>

#include <cmath>

#include "core/files.h"
#include "serve/geography.h"

using namespace squawk;
using nlohmann::json;

TEST_CASE("Geography: coastlines.dat polylines (M starts, D continues; other lines skipped)") {
  const auto lines = serve::Geography::parse_coastlines(
      "M 52.0 4.0\r\n\rD 52.5 4.5\nD 53.0 4.0\r\n# note\nM 10 10\nM 60 5\nD 61 6\nD x y\n");
  REQUIRE(lines.size() == 2);  // the lone point "M 10 10" draws nothing
  CHECK(lines[0].pts == std::vector<float>({52.0f, 4.0f, 52.5f, 4.5f, 53.0f, 4.0f}));
  CHECK(lines[0].south == 52.0f);
  CHECK(lines[0].east == 4.5f);
  CHECK(lines[1].pts.size() == 4);
}

TEST_CASE("Geography: FIR borders in degrees.minutes.seconds.ms") {
  CHECK(serve::Geography::parse_dms("N050.46.00.000") == doctest::Approx(50 + 46 / 60.0));
  CHECK(serve::Geography::parse_dms("W000.15.30.500") == doctest::Approx(-(15 / 60.0 + 30.5 / 3600)));
  CHECK(std::isnan(serve::Geography::parse_dms("N95.00.00.000")));
  CHECK(std::isnan(serve::Geography::parse_dms("X050.00.00.000")));
  CHECK(std::isnan(serve::Geography::parse_dms("N050.4a.00.000")));
  const auto f = serve::Geography::parse_fir(
      "N050.46.00.000 E006.05.00.000 \nN051.50.00.000 E006.00.00.000 \nN051.50.00.000 E006.00.00.000 \ngarbage\n", "EHAA");
  CHECK(f.name == "EHAA");
  CHECK(f.pts.size() == 4);  // the repeated point once
}

TEST_CASE("Geography: in_box keeps the lines meeting the box, thinned to the step") {
  auto none = serve::Geography::load("/nonexistent");  // no files: no lines, no error
  REQUIRE(none.is_ok());
  CHECK(none->coast().empty());
  CHECK(none->in_box({51, 54, 3, 7}, 0.01)["coast"].empty());
  const char* shared = SQUAWK_SHARED_DIR "/bluesky/navdata";
  if (!files::exists(std::string(shared) + "/coastlines.dat")) {
    MESSAGE("skipped the navdata part: " << shared << " absent");
    return;
  }
  auto nav = serve::Geography::load(shared);
  REQUIRE(nav.is_ok());
  CHECK(nav->coast().size() > 1000);
  CHECK(nav->fir().size() > 10);
  const json nl = nav->in_box({51, 54, 3, 7}, 0.01);
  CHECK(nl["coast"].size() > 0);
  bool ehaa = false;
  for (const auto& f : nl["fir"]) ehaa = ehaa || f["name"] == "EHAA";
  CHECK(ehaa);
  const json coarse = nav->in_box({-90, 90, -180, 180}, 1.0, 50000);
  size_t pts = 0;
  for (const auto& c : coarse["coast"]) pts += c.size() / 2;
  CHECK(pts <= 50000);
}

TEST_CASE("Geography: odd lines are skipped, never out of range") {
  uint64_t x = 88172645463325252ull;  // xorshift: the same text every run
  auto next = [&] { return x ^= x << 13, x ^= x >> 7, x ^= x << 17; };
  std::string coast, fir;
  for (int i = 0; i < 3000; ++i) {
    // Coastline lines with out-of-range, malformed or fine numbers.
    coast += "MDX"[next() % 3];
    coast += " " + std::to_string(static_cast<int>(next() % 400) - 200) + "." + std::to_string(next() % 100);
    coast += (next() % 7 == 0 ? " x" : " ") + std::to_string(static_cast<int>(next() % 500) - 250) + "\r\n";
    // FIR lines: a good one with a character sometimes changed, or raw bytes.
    std::string line = "N050.46.00.000 E006.05.00.000";
    if (next() % 3 == 0) line[next() % line.size()] = static_cast<char>(next() & 0xff);
    fir += line + "\n";
  }
  size_t kept = 0;
  for (const auto& l : serve::Geography::parse_coastlines(coast)) {
    REQUIRE(l.pts.size() >= 4);
    for (size_t i = 0; i < l.pts.size(); i += 2) REQUIRE((std::fabs(l.pts[i]) <= 90 && std::fabs(l.pts[i + 1]) <= 180));
    kept += l.pts.size() / 2;
  }
  CHECK(kept > 100);
  const auto f = serve::Geography::parse_fir(fir, "X");
  for (size_t i = 0; i < f.pts.size(); i += 2) REQUIRE((std::fabs(f.pts[i]) <= 90 && std::fabs(f.pts[i + 1]) <= 180));
  CHECK(f.pts.size() >= 2);
}
