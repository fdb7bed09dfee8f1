#include "translate/vocabulary.h"

#include "rag/edit_distance.h"

namespace squawk::translate {
namespace {

// True when b is a with two neighbouring letters swapped ("rihgt", "right"): one slip of the
// fingers, counted as one edit.
bool swapped_pair(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  size_t i = 0;
  while (i < a.size() && a[i] == b[i]) ++i;
  return i + 1 < a.size() && a[i] == b[i + 1] && a[i + 1] == b[i] &&
         a.compare(i + 2, std::string::npos, b, i + 2) == 0;
}

}  // namespace

Vocabulary::Vocabulary(const std::vector<std::string>& keywords, const std::vector<std::string>& fillers,
                       std::vector<std::string> spell_targets, const std::vector<std::string>& common)
    : keywords_(keywords.begin(), keywords.end()),
      fillers_(fillers.begin(), fillers.end()),
      common_(common.begin(), common.end()),
      targets_(std::move(spell_targets)) {}

std::string Vocabulary::spell_fix(const std::string& w) const {
  if (w.size() <= 3 || w.size() > 20 || is_keyword(w) || common_.count(w)) return w;
  for (char c : w)
    if (c < 'a' || c > 'z') return w;
  const size_t limit = w.size() >= 7 ? 2 : 1;
  std::string best;
  size_t best_d = limit + 1;
  bool tie = false;
  for (const auto& k : targets_) {
    if (k.empty() || k[0] != w[0] || k.size() + limit < w.size() || w.size() + limit < k.size()) continue;
    const size_t d = swapped_pair(w, k) ? 1 : rag::edit_distance(w, k);
    if (d < best_d) {
      best_d = d;
      best = k;
      tie = false;
    } else if (d == best_d && k != best) {
      tie = true;
    }
  }
  return best_d <= limit && !tie ? best : w;
}

}  // namespace squawk::translate
