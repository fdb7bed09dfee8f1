#include <doctest/doctest.h>

#include <filesystem>
#include <set>

#include "core/files.h"
#include "core/paths.h"
#include "core/rng.h"
#include "core/status.h"
#include "core/text.h"

using namespace squawk;

namespace {
Result<int> parse_positive(const std::string& s) {
  auto v = text::to_int(s);
  if (!v) return Status::invalid("'" + s + "' is not an integer");
  if (*v <= 0) return Status::invalid("expected a positive integer, got " + s);
  return static_cast<int>(*v);
}
Result<int> twice(const std::string& s) {
  SQUAWK_ASSIGN_OR_RETURN(int v, parse_positive(s));
  return 2 * v;
}
}  // namespace

TEST_CASE("Status and Result carry errors as values") {
  CHECK(Status::ok().is_ok());
  Status e = Status::not_found("no aircraft 'KL1'");
  CHECK(!e.is_ok());
  CHECK(e.code() == Code::kNotFound);
  CHECK(e.with_context("HDG KL1 90").message() == "HDG KL1 90: no aircraft 'KL1'");
  CHECK(*twice("21") == 42);
  auto bad = twice("x");
  REQUIRE(!bad.is_ok());
  CHECK(bad.status().message() == "'x' is not an integer");
  Result<int> from_ok = Status::ok();  // misuse is caught, not silently "ok"
  CHECK(!from_ok.is_ok());
  CHECK(from_ok.status().code() == Code::kInternal);
}

TEST_CASE("Rng is reproducible and uniform") {
  Rng a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const uint64_t x = a.next_u64();
    CHECK(x == b.next_u64());
    (void)c;
  }
  Rng d(7);
  std::set<int64_t> seen;
  double sum = 0, sum2 = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const int64_t k = d.uniform_int(45, 314);
    CHECK_UNARY(k >= 45 && k <= 314);
    seen.insert(k);
    const double u = d.uniform();
    sum += u;
    sum2 += u * u;
  }
  CHECK(seen.size() == 270);  // every value of the inclusive range is reachable
  CHECK(sum / n == doctest::Approx(0.5).epsilon(0.01));
  CHECK(sum2 / n - (sum / n) * (sum / n) == doctest::Approx(1.0 / 12).epsilon(0.02));
  Rng e(1);
  double m = 0, v = 0;
  for (int i = 0; i < n; ++i) {
    const double z = e.normal();
    m += z;
    v += z * z;
  }
  CHECK(m / n == doctest::Approx(0.0).epsilon(0.01).scale(1));
  CHECK(v / n == doctest::Approx(1.0).epsilon(0.02));
  Rng f(5);
  Rng g = f.fork();
  CHECK(f.next_u64() != g.next_u64());
}

TEST_CASE("text helpers") {
  CHECK(text::upper("fl350") == "FL350");
  CHECK(text::trim("  a b \t") == "a b");
  CHECK(text::split("a,,b", ',') == std::vector<std::string>{"a", "", "b"});
  CHECK(text::split_ws(" CRE  KL1\tB738 ") == std::vector<std::string>{"CRE", "KL1", "B738"});
  CHECK(text::to_double("52.5") == 52.5);
  CHECK(!text::to_double("52.5x"));
  CHECK(!text::to_double("nan"));
  CHECK(text::to_int("+12") == 12);
  CHECK(text::fmt_double(97.0) == "97");
  CHECK(text::fmt_double(-0.0000001) == "0");
  CHECK(text::fmt_double(0.78, 3) == "0.78");
  CHECK(text::iequals("Hdg", "HDG"));
}

TEST_CASE("files: atomic write then read back") {
  const std::string dir = (std::filesystem::temp_directory_path() / "squawk-test-core").string();
  REQUIRE(files::make_dirs(dir).is_ok());
  const std::string p = dir + "/x.bin";
  REQUIRE(files::write_atomic(p, std::string("a\0b", 3)).is_ok());
  auto r = files::read(p);
  REQUIRE(r.is_ok());
  CHECK(r->size() == 3);
  CHECK(!files::read(dir + "/missing").is_ok());
  CHECK(files::read(dir + "/missing").status().message().find("missing") != std::string::npos);
  CHECK(paths::is_within(dir + "/x.bin", dir));
  CHECK(!paths::is_within(dir + "/../x.bin", dir));
  CHECK(!files::write_atomic("/nonexistent-dir/x", "y").is_ok());
}
