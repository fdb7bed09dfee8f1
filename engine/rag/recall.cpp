#include "rag/recall.h"

#include <algorithm>
#include <set>

#include "command/registry.h"
#include "core/text.h"

namespace squawk::rag {

namespace {

// Canonical names of an alternative's commands; empty when one is unknown.
std::set<std::string> canonical_commands(const std::vector<std::string>& alt) {
  std::set<std::string> names;
  for (const auto& cmd : alt) {
    const auto* decl = command::Registry::instance().find(command_word(cmd));
    if (!decl) return {};
    names.insert(decl->name);
  }
  return names;
}

bool covered(const std::set<std::string>& want, const std::vector<std::string>& got, size_t k) {
  const auto end = got.begin() + static_cast<long>(std::min(k, got.size()));
  return std::all_of(want.begin(), want.end(),
                     [&](const std::string& w) { return std::find(got.begin(), end, w) != end; });
}

}  // namespace

RecallReport evaluate_recall(const Bm25Index& index, const std::vector<CorpusCase>& cases, size_t k) {
  RecallReport r;
  r.k = k;
  for (const auto& c : cases) {
    if (c.is_ask()) {
      ++r.ask_cases;
      continue;
    }
    std::vector<std::set<std::string>> wants;
    for (const auto& alt : c.alternatives())
      if (auto names = canonical_commands(alt); !names.empty()) wants.push_back(std::move(names));
    if (wants.empty()) {
      ++r.unknown_cases;
      continue;
    }
    ++r.scored;
    std::vector<std::string> got;
    for (const auto& h : index.search(c.utterance, k)) got.push_back(index.documents()[h.doc].command);
    const bool at1 = std::any_of(wants.begin(), wants.end(), [&](const auto& w) { return covered(w, got, 1); });
    const bool atk = std::any_of(wants.begin(), wants.end(), [&](const auto& w) { return covered(w, got, k); });
    r.hits_at_1 += at1;
    r.hits_at_k += atk;
    if (!atk) {
      std::string m = c.id + ": want " + text::join({wants.front().begin(), wants.front().end()}, "+");
      m.append("; got ").append(text::join(got, " "));
      r.misses.push_back(std::move(m));
    }
  }
  return r;
}

}  // namespace squawk::rag
