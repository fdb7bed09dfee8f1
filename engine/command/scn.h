// Reader of BlueSky scenario files (.scn), following stack/simstack.py readscn
// (docs/bluesky_facts.md §4.1):
//  - lines end in LF, CRLF or CR; each line is trimmed;
//  - lines shorter than 10 characters or starting with '#' are skipped;
//  - a line ending in '\' continues on the next kept line (joined by a space);
//  - text from the first '#' on is a comment;
//  - "HH:MM:SS.hh>command": the part before the first '>' is split on ':';
//    it needs at least 3 fields (int hours, int minutes, real seconds; more
//    fields are ignored); a line whose timestamp does not parse is reported
//    in `rejected` and skipped;
//  - entries are stable-sorted by time.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/status.h"

namespace squawk::command {

struct ScnEntry {
  double time = 0.0;    // [s] from the scenario start
  std::string command;  // TrafScript text after '>' (may hold several ';' commands)
  int line = 0;         // 1-based line number in the file where the entry starts
};

struct ScnRejected {
  int line = 0;      // 1-based
  std::string text;  // the offending line, trimmed
};

struct ScnFile {
  std::vector<ScnEntry> entries;      // sorted by time, stable
  std::vector<ScnRejected> rejected;  // lines with an unreadable timestamp
};

// Parses scenario text; never fails (bad lines land in `rejected`).
ScnFile parse_scn(std::string_view text);

// Reads and parses a file. Error: the file cannot be read.
Result<ScnFile> read_scn(const std::string& path);

}  // namespace squawk::command
