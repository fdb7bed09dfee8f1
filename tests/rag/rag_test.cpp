// BM25 retrieval over the command registry, corpus reading and Recall@K.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "command/registry.h"
#include "core/files.h"
#include "core/paths.h"
#include "rag/bm25.h"
#include "rag/corpus.h"
#include "rag/notes.h"
#include "rag/recall.h"
#include "rag/tokenize.h"

using namespace squawk::rag;

namespace {

std::string temp_file(const std::string& name, const std::string& content) {
  const std::string path = "/tmp/squawk_rag_test_" + name;
  std::ofstream(path) << content;
  return path;
}

}  // namespace

TEST_CASE("tokenize lowers, drops stop words and numbers, folds suffixes") {
  CHECK(tokenize("Climb the aircraft to 30000 feet") == std::vector<std::string>{"climb", "aircraft", "feet"});
  CHECK(stem("climbing") == stem("climbs"));
  CHECK(stem("climbed") == "climb");
  CHECK(stem("waypoints") == "waypoint");
  CHECK(tokenize("FL300 KL204") == std::vector<std::string>{"fl", "kl"});
}

TEST_CASE("BM25 scores match a hand computation") {
  // Two documents; query "heading": n = 1, N = 2, f = 1, |d0| = 2, avgdl = 2.
  Bm25Index idx({{"HDG", "heading turn"}, {"ALT", "altitude climb"}});
  auto hits = idx.search("heading", 5);
  REQUIRE(hits.size() == 1);
  CHECK(hits[0].doc == 0);
  const double idf = std::log(1.0 + (2 - 1 + 0.5) / (1 + 0.5));
  CHECK(hits[0].score == doctest::Approx(idf * 1 * 2.2 / (1 + 1.2)));
  CHECK(idx.search("nothing matches", 5).empty());
  // A longer document with the same term count scores lower (length norm).
  Bm25Index idx2({{"A", "turn"}, {"B", "turn left right now quickly"}, {"C", "other"}});
  auto h2 = idx2.search("turn", 2);
  REQUIRE(h2.size() == 2);
  CHECK(h2[0].doc == 0);
  CHECK(h2[0].score > h2[1].score);
}

TEST_CASE("an unknown query word one edit from an indexed term stands for it") {
  Bm25Index idx({{"HDG", "heading turn"}, {"DEL", "delete remove"}});
  auto first = [&](const char* q) { auto h = idx.search(q, 1); return h.empty() ? size_t{99} : h[0].doc; };
  CHECK(first("dleete") == 1);  // swap of neighbours
  CHECK(first("tunr") == 0);
  CHECK(first("delate") == 1);  // substitution
  CHECK(first("turnn") == 0);   // insertion
  CHECK(idx.search("trn", 1).empty());         // too short to guess
  CHECK(idx.search("dlt", 1).empty());         // more than one edit
}

TEST_CASE("registry documents carry name, aliases, usage, help and examples") {
  const auto& reg = squawk::command::Registry::instance();
  auto docs = registry_documents(reg);
  REQUIRE(docs.size() == reg.commands().size());
  const auto* hdg = reg.find("HDG");
  REQUIRE(hdg != nullptr);
  for (const auto& d : docs) {
    if (d.command != hdg->name) continue;
    CHECK(d.text.find(hdg->usage) != std::string::npos);
    CHECK(d.text.find(hdg->help) != std::string::npos);
  }
  Bm25Index idx(docs);
  auto hits = idx.search("change the heading of the aircraft", 5);
  REQUIRE_FALSE(hits.empty());
  bool found = false;
  for (const auto& h : hits) found = found || idx.documents()[h.doc].command == hdg->name;
  CHECK(found);
}

TEST_CASE("notes attach to the command they name, aliases folded; bad lines are errors") {
  const auto path = temp_file("notes.txt", "# comment\n\nHEADING: vector the traffic onto a zyxwv course\n");
  auto notes = read_notes(path);
  REQUIRE_MESSAGE(notes.is_ok(), notes.status().message());
  REQUIRE(notes->size() == 1);
  const auto& reg = squawk::command::Registry::instance();
  auto docs = command_documents(reg, *notes);
  CHECK(docs.size() == reg.commands().size());
  Bm25Index idx(docs);
  auto hits = idx.search("zyxwv", 1);
  REQUIRE(hits.size() == 1);
  CHECK(idx.documents()[hits[0].doc].command == reg.find("HDG")->name);

  auto bad = read_notes(temp_file("bad.txt", "this line has no name\n"));
  REQUIRE_FALSE(bad.is_ok());
  CHECK(bad.status().message().find(":1:") != std::string::npos);
  CHECK_FALSE(read_notes("/nonexistent/notes.txt").is_ok());
}

TEST_CASE("corpus reader: alternatives, ASK, bad files") {
  const auto path = temp_file("corpus.tsv",
                              "id\tsetup\tutterance\texpected\tcategory\n"
                              "c1\t\tturn KL1 west\tHDG KL1 270 || HEADING KL1 270\theading\n"
                              "c2\t\tdo something\tASK\task\n"
                              "c3\tCRE A B 1 2 3 4 5\tclimb and turn\tALT A FL300 ; HDG A 90\tmulti\n");
  auto cases = read_corpus(path);
  REQUIRE_MESSAGE(cases.is_ok(), cases.status().message());
  REQUIRE(cases->size() == 3);
  CHECK((*cases)[0].alternatives().size() == 2);
  CHECK((*cases)[1].is_ask());
  CHECK((*cases)[2].alternatives()[0] == std::vector<std::string>{"ALT A FL300", "HDG A 90"});
  CHECK(command_word(" hdg KL1 90") == "HDG");

  auto bad = read_corpus(temp_file("bad.tsv", "id\tsetup\tutterance\texpected\tcategory\nc1\tonly two\n"));
  REQUIRE_FALSE(bad.is_ok());
  CHECK(bad.status().message().find(":2:") != std::string::npos);
  CHECK_FALSE(read_corpus(temp_file("hdr.tsv", "a\tb\n")).is_ok());
}

TEST_CASE("recall counts hits, ASK and unknown commands apart") {
  Bm25Index idx({{"HDG", "heading turn"}, {"ALT", "altitude climb descend"}});
  std::vector<CorpusCase> cases = {{"1", "", "turn left", "HDG A 90", "heading"},
                                   {"2", "", "climb to FL300", "ALT A FL300", "altitude"},
                                   {"3", "", "climb", "HDG A 90", "heading"},
                                   {"4", "", "hm", "ASK", "ask"},
                                   {"5", "", "x", "NOSUCHCMD 1", "other"}};
  auto r = evaluate_recall(idx, cases, 1);
  CHECK(r.scored == 3);
  CHECK(r.hits_at_1 == 2);
  CHECK(r.ask_cases == 1);
  CHECK(r.unknown_cases == 1);
  REQUIRE(r.misses.size() == 1);
  CHECK(r.misses[0].rfind("3:", 0) == 0);
}

TEST_CASE("Recall@5 on the development corpus, registry documentation alone" * doctest::test_suite("shared")) {
  const std::string path = std::string(SQUAWK_SHARED_DIR) + "/corpora/nl2trafscript_dev.tsv";
  if (!squawk::files::exists(path)) {
    MESSAGE("skipped: " << path << " is absent");
    return;
  }
  auto cases = read_corpus(path);
  REQUIRE(cases.is_ok());
  Bm25Index idx(command_documents(squawk::command::Registry::instance(), {}));
  auto r = evaluate_recall(idx, *cases, 5);
  MESSAGE("Recall@1 " << r.recall_at_1() << ", Recall@5 " << r.recall_at_k() << " over " << r.scored << " cases");
  CHECK(r.scored > 150);
  CHECK(r.recall_at_k() > 0.7);
}
