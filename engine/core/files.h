// File helpers behind one small interface: whole-file read and atomic write.
#pragma once

#include <string>

#include "core/status.h"

namespace squawk::files {

// Reads a whole file as bytes. Error names the path and the OS reason.
Result<std::string> read(const std::string& path);
// Writes `data` to `path` atomically: a temp file in the same folder, flushed,
// then renamed over `path`. A crash leaves either the old or the new file.
Status write_atomic(const std::string& path, const std::string& data);
bool exists(const std::string& path);
// Creates a folder and its parents (ok if it exists).
Status make_dirs(const std::string& path);

}  // namespace squawk::files
