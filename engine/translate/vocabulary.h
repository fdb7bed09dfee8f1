// The instruction vocabulary of the offline grammar and a spelling fixer.
//
// Contract: is_keyword() is true for words that carry meaning in an
// instruction (verbs, units, nouns such as "altitude"); spell_fix() returns
// the instruction word a misspelt word stands for ("heding" -> "heading",
// "tunr" -> "turn", "kots" -> "knots") when exactly one such word with the same first
// letter is one edit away (two for words of 7+ letters; a swap of adjacent
// letters is one edit), else the word unchanged. Words of 3 letters or
// fewer, and known words, are never changed.
#pragma once

#include <string>

namespace squawk::translate {

bool is_keyword(const std::string& w);
bool is_filler(const std::string& w);  // "ah", "uh", "please", "the", ...
std::string spell_fix(const std::string& w);

}  // namespace squawk::translate
