#include "rag/tokenize.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace squawk::rag {

namespace {

constexpr std::array<std::string_view, 48> kStopWords = {
    "a",     "an",   "and",  "are",   "as",   "at",   "be",   "by",   "can",  "could", "do",  "for",
    "from",  "i",    "in",   "is",    "it",   "its",  "me",   "my",   "of",   "on",    "or",  "our",
    "please", "so",  "that", "the",   "then", "this", "to",   "us",   "we",   "will",  "with", "would",
    "you",   "your", "want", "should", "let", "lets", "now",  "give", "need", "some",  "there", "what"};

bool is_stop(std::string_view w) {
  return std::find(kStopWords.begin(), kStopWords.end(), w) != kStopWords.end();
}

bool ends_with(std::string_view w, std::string_view suf) {
  return w.size() > suf.size() && w.substr(w.size() - suf.size()) == suf;
}

}  // namespace

std::string stem(std::string_view w) {
  std::string s(w);
  if (s.size() <= 3) return s;
  if (ends_with(s, "ies")) return s.substr(0, s.size() - 3) + "y";
  if (ends_with(s, "ing") && s.size() > 5) s.resize(s.size() - 3);
  else if (ends_with(s, "ed") && s.size() > 4) s.resize(s.size() - 2);
  else if (ends_with(s, "es") && s.size() > 4 && (ends_with(s, "ses") || ends_with(s, "xes")))
    s.resize(s.size() - 2);
  else if (ends_with(s, "s") && !ends_with(s, "ss") && s.size() > 3) s.resize(s.size() - 1);
  if (s.size() > 3 && s.back() == 'e') s.pop_back();  // "move"/"moving" -> "mov"
  if (s.size() > 3 && s[s.size() - 1] == s[s.size() - 2] && !std::isdigit(static_cast<unsigned char>(s.back())))
    s.pop_back();  // "stopp(ing)" -> "stop"
  return s;
}

std::vector<std::string> tokenize(std::string_view text) {
  std::vector<std::string> out;
  std::string word;
  auto flush = [&] {
    if (word.empty()) return;
    const bool numeric = std::all_of(word.begin(), word.end(), [](unsigned char c) { return std::isdigit(c); });
    if (!numeric && !is_stop(word)) out.push_back(stem(word));
    word.clear();
  };
  for (char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    const bool digit = std::isdigit(c) != 0;
    if (!word.empty() && digit != (std::isdigit(static_cast<unsigned char>(word.back())) != 0)) flush();
    if (std::isalnum(c)) word.push_back(static_cast<char>(std::tolower(c)));
    else flush();
  }
  flush();
  return out;
}

}  // namespace squawk::rag
