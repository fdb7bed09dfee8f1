// The one edit distance of squawk (retrieval's typo folding, the grammar's
// spelling fixer, callsign and fix matching, the "did you mean" of unknown
// commands).
//
// Contract: optimal string alignment distance, byte-wise and case-sensitive:
// an insertion, a deletion, a substitution or a swap of two neighbouring
// characters each cost 1 ("tunr" -> "turn" is 1). Pure; O(|a|·|b|) time,
// O(|b|) memory.
#pragma once

#include <cstddef>
#include <string_view>

namespace squawk::text {

size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace squawk::text
