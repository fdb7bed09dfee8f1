// A numeric CSV table: one header line, comma-separated values.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"

namespace squawk::viz {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;  // NaN where a cell is not a number
  // Index of `name` in columns, or -1.
  int column(const std::string& name) const;
  std::vector<double> values(int col) const;
};

// Errors name the line that has the wrong number of cells.
Result<Table> parse_csv(const std::string& text);

}  // namespace squawk::viz
