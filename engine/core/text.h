// Small text helpers shared by the parsers. ASCII semantics throughout.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace squawk::text {

std::string upper(std::string_view s);
std::string lower(std::string_view s);
std::string_view trim(std::string_view s);
bool iequals(std::string_view a, std::string_view b);
bool starts_with_ci(std::string_view s, std::string_view prefix);
// Splits on every occurrence of `sep`; keeps empty fields.
std::vector<std::string> split(std::string_view s, char sep);
// Splits on runs of ASCII whitespace; no empty fields.
std::vector<std::string> split_ws(std::string_view s);
std::string join(const std::vector<std::string>& parts, std::string_view sep);
// Parses the whole of `s` (after trimming) as a finite double / integer.
std::optional<double> to_double(std::string_view s);
std::optional<long long> to_int(std::string_view s);
// Shortest decimal text that reads back to the same double ("%.17g" trimmed).
std::string fmt_double(double v, int max_decimals = 6);
// The double as given, for messages that must show a bad value: "%.17g"
// (every digit, exponents, nan and inf as the C library writes them).
std::string fmt_exact(double v);
// Quotes a string for messages: 'FL9X'; control bytes appear as \xNN.
std::string quoted(std::string_view s);

}  // namespace squawk::text
