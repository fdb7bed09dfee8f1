// The instruction vocabulary of the offline grammar and a spelling fixer.
// The words live in Lua (scripts/translate/lexicon.lua: keywords, fillers,
// spelling.targets, spelling.common) and reach C++ with the name tables.
//
// Contract: is_keyword() is true for words that carry meaning in an
// instruction (verbs, units, nouns such as "altitude"); is_filler() for
// words that carry none ("uh", "please"); spell_fix() returns the target
// word a misspelt word stands for ("heding" -> "heading", "tunr" -> "turn")
// when exactly one target with the same first letter is one edit away (two
// for words of 7+ letters; rag/edit_distance.h), else the word unchanged.
// Words of 3 letters or fewer or over 20, keywords and common words are
// never changed.
#pragma once

#include <string>
#include <unordered_set>
#include <vector>

namespace squawk::translate {

class Vocabulary {
 public:
  Vocabulary() = default;
  Vocabulary(const std::vector<std::string>& keywords, const std::vector<std::string>& fillers,
             std::vector<std::string> spell_targets, const std::vector<std::string>& common);

  bool is_keyword(const std::string& w) const { return keywords_.count(w) > 0; }
  bool is_filler(const std::string& w) const { return fillers_.count(w) > 0; }
  std::string spell_fix(const std::string& w) const;

 private:
  std::unordered_set<std::string> keywords_, fillers_, common_;
  std::vector<std::string> targets_;
};

}  // namespace squawk::translate
