// Numbers as people say or type them.
//
// Contract: read_number() reads the number that starts at token i:
//  - a typed number, optionally followed by "hundred" / "thousand";
//  - cardinal words ("thirty one thousand", "one hundred and twenty",
//    "twelve hundred", "four thousand five hundred");
//  - ATC digit-by-digit and grouped forms ("one two zero", "niner", "fife",
//    "tree", "one eighty", "fifty one twenty"): adjacent groups concatenate;
//  - hesitations ("ah", "uh", "um", "er") between groups are skipped;
//  - digits said singly or grouped after "thousand" end the number ("one one
//    thousand two five zero", "seven thousand two twenty": 11000, 7000;
//    "four thousand five hundred" is one number);
//  - a decimal part after "point" / "decimal" ("point seven eight" = 0.78),
//    unless "thousand"/"hundred" follows (speech errors for "descend");
//  - a fraction after a whole number said with no multiplier, and a multiplier
//    after the fraction ("two and a half" = 2.5, "2 and a quarter" = 2.25,
//    "one and three quarters", "one and a half thousand" = 1500); none is read
//    after "hundred"/"thousand" ("four thousand and a half" ends at 4000).
// `digits` is the concatenation of the spoken groups with multipliers left
// out ("fifty one twenty" -> "5120"), which is how callsign digits are read.
// Returns nullopt when no number starts at i.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "translate/lexer.h"

namespace squawk::translate {

struct SpokenNumber {
  double value = 0.0;
  std::string digits;         // groups concatenated, no multipliers
  size_t begin = 0;           // first token
  size_t end = 0;             // one past the last token
  bool typed = false;         // a digit token, not words
  bool has_thousand = false;  // "thousand" (or typed then "thousand") was said
  bool has_hundred = false;
  bool has_decimal = false;
  int groups = 0;                   // spoken groups ("one eighty" = 2)
  bool leading_digit_word = false;  // first group is a single digit word
};

// Speech recognition writes digits as words that sound alike: between two
// digit words, "to"/"too" is two, "on"/"won"/"once"/"ones" one, "for" four,
// "ate"/"hate"/"a" eight, "fine" five ("two on zero" = 210, "one a four" = 184); "fine" also after
// two digits
// ("three three fine" = 335); "won"/"once"/"ones"/"ate"/"fine"/"for" also after a
// digit at the end ("speed two once" = 21, "mach decimal seven for" = .74). "hate", "too" and "won"
// before any number word are digits ("too too zero" = 220, "too thousand"), "hate" and "won" after
// a digit too, and "too" before a side of the globe ("too west"). Rewrites those tokens' text in
// place. A word joined by hyphens of number words only ("forty-five",
// "four-fifty-one", "three-oh-two", "one-double-zero") is those words said
// apart ("oh"/"o" after the first part is zero). A lone lower-case letter, or
// another word hyphen-glued to a digit word, between two digit words ("three
// f four zero", "one nine-year zero") is noise and is removed.
void fold_digit_homophones(std::vector<Token>& toks);

// The digit a word that sounds like one stands for, as fold_digit_homophones
// reads it ("for" = 4, "to"/"too" = 2, "won"/"on"/"once"/"ones" = 1,
// "ate"/"a" = 8, "fine" = 5), or -1.
int heard_digit(const std::string& w);
// Value 0-9 of a digit word ("niner" = 9, "fife" = 5), or -1.
int digit_word(const std::string& w);
// True when the token can start or continue a spoken number.
bool is_number_word(const Token& t);

std::optional<SpokenNumber> read_number(const std::vector<Token>& toks, size_t i);

}  // namespace squawk::translate
