#include "translate/fuzzy.h"

#include "rag/edit_distance.h"

#include <algorithm>
#include <cctype>

namespace squawk::translate {
namespace {

std::string letters_digits(std::string_view s) {
  std::string r;
  for (char c : s)
    if (std::isalnum(static_cast<unsigned char>(c))) r += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

char fold(char c) {
  switch (c) {
    case 'c': case 'k': case 'q': case 'g': return 'k';
    case 's': case 'z': case 'x': return 's';
    case 'd': case 't': return 't';
    case 'b': case 'p': return 'p';
    case 'f': case 'v': return 'f';
    case 'm': case 'n': return 'n';
    default: return c;
  }
}

bool vowel(char c) { return c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u' || c == 'y' || c == 'h' || c == 'w'; }

}  // namespace

double plain_similarity(std::string_view a, std::string_view b) {
  std::string x = letters_digits(a), y = letters_digits(b);
  size_t n = std::max(x.size(), y.size());
  if (n == 0) return 1.0;
  return 1.0 - static_cast<double>(rag::edit_distance(x, y)) / static_cast<double>(n);
}

std::string sound_key(std::string_view s) {
  std::string x = letters_digits(s), k;
  for (size_t i = 0; i < x.size(); ++i) {
    char c = x[i];
    if (i > 0 && vowel(c)) continue;
    char f = i == 0 && vowel(c) ? 'a' : fold(c);
    if (!k.empty() && k.back() == f) continue;
    k += f;
  }
  return k;
}

double similarity(std::string_view a, std::string_view b) {
  return std::max(plain_similarity(a, b), plain_similarity(sound_key(a), sound_key(b)));
}

std::optional<Match> best_match(std::string_view spoken, const std::vector<std::string>& candidates) {
  if (candidates.empty()) return std::nullopt;
  Match m;
  m.score = -1.0;
  for (size_t i = 0; i < candidates.size(); ++i) {
    double s = similarity(spoken, candidates[i]);
    if (s > m.score) m = {i, s};
  }
  return m;
}

}  // namespace squawk::translate
