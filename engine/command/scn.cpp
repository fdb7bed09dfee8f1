#include "command/scn.h"

#include <algorithm>

#include "core/files.h"
#include "core/text.h"

namespace squawk::command {

namespace {

// Seconds from "H:M:S[...]" (at least 3 fields); nullopt when unreadable.
std::optional<double> timestamp(std::string_view stamp) {
  const auto f = text::split(text::trim(stamp), ':');
  if (f.size() < 3) return std::nullopt;
  auto h = text::to_int(f[0]);
  auto m = text::to_int(f[1]);
  auto s = text::to_double(f[2]);
  if (!h || !m || !s) return std::nullopt;
  const double t = static_cast<double>(*h) * 3600.0 + static_cast<double>(*m) * 60.0 + *s;
  if (!(t > -1e9 && t < 1e9)) return std::nullopt;
  return t;
}

}  // namespace

ScnFile parse_scn(std::string_view data) {
  ScnFile out;
  std::string pending;  // text of a line continued with '\'
  int pending_line = 0;
  int lineno = 0;
  size_t start = 0;
  while (start <= data.size()) {
    size_t end = start;
    while (end < data.size() && data[end] != '\n' && data[end] != '\r') ++end;
    if (end == data.size() && start == data.size()) break;
    const std::string_view raw = data.substr(start, end - start);
    start = end + 1;
    if (end < data.size() && data[end] == '\r' && end + 1 < data.size() && data[end + 1] == '\n') ++start;
    ++lineno;

    const std::string_view trimmed = text::trim(raw);
    if (trimmed.size() < 10 || trimmed.front() == '#') continue;
    std::string line = pending;
    line.append(trimmed);
    const int first_line = pending.empty() ? lineno : pending_line;
    if (line.back() == '\\') {
      line.pop_back();
      pending = std::string(text::trim(line));
      pending.push_back(' ');
      pending_line = first_line;
      continue;
    }
    pending.clear();

    std::string_view content = line;
    if (auto hash = content.find('#'); hash != std::string_view::npos) content = content.substr(0, hash);
    content = text::trim(content);
    const size_t gt = content.find('>');
    std::optional<double> t;
    if (gt != std::string_view::npos) t = timestamp(content.substr(0, gt));
    if (!t) {
      out.rejected.push_back({first_line, std::string(content)});
      continue;
    }
    out.entries.push_back({*t, std::string(text::trim(content.substr(gt + 1))), first_line});
  }
  std::stable_sort(out.entries.begin(), out.entries.end(),
                   [](const ScnEntry& a, const ScnEntry& b) { return a.time < b.time; });
  return out;
}

Result<ScnFile> read_scn(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string data, files::read(path));
  return parse_scn(data);
}

}  // namespace squawk::command
