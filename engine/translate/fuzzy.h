// Fuzzy matching of spoken names against the names that exist.
//
// Contract: similarity() is in [0, 1], 1 for equal strings (case ignored);
// it is the larger of the Levenshtein similarity of the letters and of a
// sound key (vowels after the first letter dropped, similar consonants
// folded: "gale" ~ "GAYEL", "tiger" ~ "TYGGR"). Pure functions, no state.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace squawk::translate {

// 1 - edit distance (rag/edit_distance.h) / longer length, on lower-cased
// letters and digits only.
double plain_similarity(std::string_view a, std::string_view b);
std::string sound_key(std::string_view s);
double similarity(std::string_view a, std::string_view b);

struct Match {
  size_t index = 0;    // into the candidate list
  double score = 0.0;  // similarity of the best candidate
};
// Best candidate by similarity(); nullopt when `candidates` is empty.
std::optional<Match> best_match(std::string_view spoken, const std::vector<std::string>& candidates);

}  // namespace squawk::translate
