// Tokens for BM25: lower-case ASCII words with a light suffix stemmer.
//
// Contract: splits on every character that is not a letter or digit and
// between letters and digits ("FL300" -> "fl", "300"), lowers
// case, drops English stop words and bare numbers (values say nothing about
// which command is meant), and folds common suffixes so that "climbing",
// "climbs" and "climbed" meet "climb". Deterministic; no locale.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace squawk::rag {

std::vector<std::string> tokenize(std::string_view text);
// The stem of one lower-case word.
std::string stem(std::string_view word);

}  // namespace squawk::rag
