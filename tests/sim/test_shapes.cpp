// Named shapes (sim/shapes.h): BlueSky's checkInside for boxes, circles,
// polygons and lines, and the checks on definition.
#include <doctest/doctest.h>

#include "core/units.h"
#include "sim/shapes.h"

using namespace squawk;
using namespace squawk::sim;

TEST_CASE("contains: box inclusive, circle by kwikdist in NM, polygon even-odd, line never") {
  const Shape box{Shape::Kind::kBox, {53, 5, 51, 3}, 1e9, -1e9};  // corners in any order
  CHECK(box.contains(52, 4, 0));
  CHECK(box.contains(51, 3, 0));  // on the corner
  CHECK(!box.contains(53.01, 4, 0));
  const Shape circle{Shape::Kind::kCircle, {52, 4, 10}, 1e9, -1e9};
  CHECK(circle.contains(52 + 9.9 / 60, 4, 0));   // 9.9 NM north
  CHECK(!circle.contains(52 + 10.1 / 60, 4, 0));
  // A concave "U": the notch between its arms is outside.
  const Shape u{Shape::Kind::kPoly, {50, 0, 50, 3, 53, 3, 53, 2, 51, 2, 51, 1, 53, 1, 53, 0}, 1e9, -1e9};
  CHECK(u.contains(50.5, 1.5, 0));
  CHECK(u.contains(52, 0.5, 0));
  CHECK(!u.contains(52, 1.5, 0));
  const Shape line{Shape::Kind::kLine, {50, 0, 53, 3}, 1e9, -1e9};
  CHECK(!line.contains(51.5, 1.5, 0));
  const Shape layer{Shape::Kind::kBox, {51, 3, 53, 5}, 8000.0, 3000.0};
  CHECK(layer.contains(52, 4, 5000));
  CHECK(!layer.contains(52, 4, 9000));
  CHECK(!layer.contains(52, 4, 1000));
}

TEST_CASE("define: errors name the shape and the value; replace; remove") {
  ShapeSet set;
  CHECK(set.define("A", {Shape::Kind::kBox, {51, 3, 53, 5}}).is_ok());
  CHECK(set.define("A", {Shape::Kind::kCircle, {52, 4, 5}}).is_ok());  // replaced
  CHECK(set.find("A")->kind == Shape::Kind::kCircle);
  auto st = set.define("B", {Shape::Kind::kPoly, {91, 0, 52, 1, 53, 2}});
  CHECK(st.message().find("shape 'B': latitude 91") != std::string::npos);
  CHECK(!set.define("C", {Shape::Kind::kLine, {52, 4}}).is_ok());
  CHECK(!set.define("D", {Shape::Kind::kCircle, {52, 4, 0}}).is_ok());
  CHECK(!set.define("", {Shape::Kind::kBox, {51, 3, 53, 5}}).is_ok());
  CHECK(set.remove("A"));
  CHECK(!set.remove("A"));
  CHECK(set.all().empty());
}
