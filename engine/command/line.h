// BlueSky's TrafScript line rules: splitting a line into commands and a
// command into argument tokens.
//
// Rules (docs/bluesky_facts.md §2.1):
//  - `;` separates commands on one line (split_commands).
//  - A token runs to the first whitespace or comma; a token that starts with
//    ' or " runs to the closing quote (the quotes are dropped).
//  - After a token, whitespace, at most ONE comma, and more whitespace are
//    consumed, so `A,B`, `A B` and `A , B` are the same two tokens.
//  - An argument whose text starts with a comma (e.g. the middle of `a,,b`)
//    is "omitted": the parameter takes its default.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace squawk::command {

// Splits a line on `;` into commands, trimmed; empty pieces are dropped.
std::vector<std::string> split_commands(std::string_view line);

// Reads argument tokens from the text after a command name.
class ArgReader {
 public:
  explicit ArgReader(std::string_view text);

  // True when no text is left.
  bool at_end() const { return rest_.empty(); }
  // True when the next argument is omitted: no text is left, or the text
  // starts with a comma.
  bool next_omitted() const { return rest_.empty() || rest_.front() == ','; }
  // Consumes and returns the next token ("" for an omitted one).
  std::string next();
  // The unconsumed text (for `string` arguments that take the rest of the line).
  std::string_view rest() const { return rest_; }
  // Consumes everything.
  void clear() { rest_ = {}; }

 private:
  std::string_view rest_;
};

// All tokens of `text`, omitted ones as "".
std::vector<std::string> tokenize(std::string_view text);

}  // namespace squawk::command
