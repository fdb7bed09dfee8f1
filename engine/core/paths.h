// Where squawk finds its shipped files (scripts/, prompts/, scenarios/).
#pragma once

#include <string>

namespace squawk::paths {

// The squawk home: $SQUAWK_HOME if set, else the source tree this binary was
// built from, else the current folder.
std::string home();
// home() + "/" + rel.
std::string resource(const std::string& rel);
// The canonical absolute form of `p` (lexically normalised if it does not exist).
std::string absolute(const std::string& p);
// True when `p` lies inside folder `dir` (both made absolute first).
bool is_within(const std::string& p, const std::string& dir);
// The folder part of a file path ("." when none).
std::string dirname(const std::string& p);

}  // namespace squawk::paths
