// The shared corpora: accuracy floors of the offline translator.
#include <doctest/doctest.h>

#include <chrono>

#include "core/files.h"
#include "translate/corpus.h"

using namespace squawk;
using namespace squawk::translate;

namespace {

void check_floor(const char* name, double floor) {
  const std::string path = std::string(SQUAWK_SHARED_DIR) + "/corpora/" + name;
  if (!files::exists(path)) {
    MESSAGE("skipped: " << path << " is absent (the shared corpora live beside the repository)");
    return;
  }
  auto cases = read_corpus(path);
  REQUIRE_MESSAGE(cases.is_ok(), cases.status().message());
  auto r = evaluate(*cases, translate_case_offline);
  MESSAGE(format_report(r, path));
  CHECK(r.accuracy() >= floor);
}

}  // namespace

TEST_CASE("offline accuracy on the development corpus is at least 95 %") { check_floor("nl2trafscript_dev.tsv", 0.95); }

TEST_CASE("offline accuracy on the vice speech corpus is at least 85 %") { check_floor("vice_trafscript.tsv", 0.85); }
