// Lexer for controller and experimenter English.
//
// Contract: splits an utterance into tokens that the offline grammar reads.
//  - words are lower-cased (`raw` keeps the original spelling, used for ids);
//  - typed numbers become kNumber tokens ("41,000" -> 41000, "0.5", ".78",
//    "-1000");
//    a unit glued to a number is split off ("30k" -> 30 "k", "250kt" -> 250
//    "kt", "52.3N" -> 52.3 "n", "FL250" -> "fl" 250, "M.78" -> "mach" 0.78,
//    "N52.3" -> "n" 52.3);
//  - degree/minute forms ("N52°18.6'", "52°18'N") become one kNumber in
//    decimal degrees with a hemisphere word beside it;
//  - hyphenated words split ("thirty-one", "fast-forward"), except tokens
//    with digits ("737-800", "ASAS-01.scn");
//  - text inside double quotes is one kQuoted token;
//  - punctuation that separates clauses (, . ; : ? !) becomes kPunct.
// Alphanumeric identifiers ("AC01", "DLH4AB", "demo.scn") are kWord tokens
// whose `raw` holds the spelling as typed. Never fails; input of any bytes
// yields some token list.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace squawk::translate {

enum class TokKind { kWord, kNumber, kPunct, kQuoted };

struct Token {
  TokKind kind = TokKind::kWord;
  std::string text;     // lower-case word, punctuation char, or quoted text
  std::string raw;      // as written (case kept)
  double num = 0.0;     // value of a kNumber
  bool spelled = false; // kNumber only: written with a decimal point or glued unit
  bool glued = false;   // written with no space after the previous token ("N" "52.3" from "N52.3")
};

std::vector<Token> lex(std::string_view utterance);

// True when `s` mixes letters and digits or is an identifier-like token
// (letters, digits, '.', '/', '-', '_'): candidates for callsigns, files, fixes.
bool has_digit(std::string_view s);
bool is_alpha(std::string_view s);

}  // namespace squawk::translate
