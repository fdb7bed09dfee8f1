#include "viz/csv.h"

#include <limits>

#include "core/text.h"

namespace squawk::viz {

int Table::column(const std::string& name) const {
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

std::vector<double> Table::values(int col) const {
  std::vector<double> v;
  if (col < 0) return v;
  for (const auto& r : rows) v.push_back(r[static_cast<size_t>(col)]);
  return v;
}

Result<Table> parse_csv(const std::string& text) {
  Table t;
  size_t line_no = 0;
  for (const auto& raw : text::split(text, '\n')) {
    ++line_no;
    const auto line = text::trim(raw);
    if (line.empty()) continue;
    auto cells = text::split(line, ',');
    if (t.columns.empty()) {
      for (auto& c : cells) t.columns.emplace_back(text::trim(c));
      continue;
    }
    if (cells.size() != t.columns.size())
      return Status::corruption("CSV line " + std::to_string(line_no) + " has " +
                                std::to_string(cells.size()) + " cells, the header has " +
                                std::to_string(t.columns.size()));
    std::vector<double> row;
    for (const auto& c : cells)
      row.push_back(text::to_double(c).value_or(std::numeric_limits<double>::quiet_NaN()));
    t.rows.push_back(std::move(row));
  }
  if (t.columns.empty()) return Status::corruption("CSV has no header line");
  return t;
}

}  // namespace squawk::viz
