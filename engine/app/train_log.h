// log.csv of a training run: one row per evaluation interval, first column
// the episodes trained so far.
#pragma once

#include <string>

#include "core/status.h"

namespace squawk::app {

// Keeps the header and the rows of `path` whose episodes are <= `episodes`
// (the resumed checkpoint's). Rows written after the checkpoint that failed
// to save (a full disk) are dropped, so --resume never repeats a row.
Status trim_log(const std::string& path, long long episodes);

}  // namespace squawk::app
