#include "command/line.h"

#include "core/text.h"

namespace squawk::command {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

void skip_space(std::string_view& s) {
  size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  s.remove_prefix(i);
}

}  // namespace

std::vector<std::string> split_commands(std::string_view line) {
  std::vector<std::string> out;
  for (const auto& piece : text::split(line, ';')) {
    std::string_view t = text::trim(piece);
    if (!t.empty()) out.emplace_back(t);
  }
  return out;
}

ArgReader::ArgReader(std::string_view text) : rest_(text) { skip_space(rest_); }

std::string ArgReader::next() {
  std::string_view s = rest_;
  skip_space(s);
  std::string token;
  if (!s.empty() && (s.front() == '\'' || s.front() == '"')) {
    s.remove_prefix(1);
    size_t end = 0;
    while (end < s.size() && s[end] != '\'' && s[end] != '"') ++end;
    token.assign(s.substr(0, end));
    s.remove_prefix(end);
    if (!s.empty()) s.remove_prefix(1);  // the closing quote
  } else {
    size_t end = 0;
    while (end < s.size() && !is_space(s[end]) && s[end] != ',') ++end;
    token.assign(s.substr(0, end));
    s.remove_prefix(end);
  }
  skip_space(s);
  if (!s.empty() && s.front() == ',') s.remove_prefix(1);
  skip_space(s);
  rest_ = s;
  return token;
}

std::vector<std::string> tokenize(std::string_view text) {
  std::vector<std::string> out;
  ArgReader r(text);
  while (!r.at_end()) out.push_back(r.next());
  return out;
}

}  // namespace squawk::command
