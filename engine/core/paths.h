// Where squawk finds its shipped files (scripts/, prompts/, scenarios/).
#pragma once

#include <string>

namespace squawk::paths {

// The squawk home, the folder holding scripts/ prompts/ scenarios/ models/:
// $SQUAWK_HOME if set; else found from the running executable: its folder's
// parent (a build folder inside a checkout: build/squawk), its
// ../share/squawk (an install by `cmake --install`), or its own folder; else
// the current folder when it has scripts/; else ".". A moved checkout or a
// copied install therefore uses its own files, never the tree it was built in.
std::string home();
// home() + "/" + rel.
std::string resource(const std::string& rel);
// A path to store in files that outlive this home (checkpoints): a path inside
// home() becomes "@home/REL", others stay as given. resolve() undoes it
// against the current home.
std::string portable(const std::string& p);
std::string resolve(const std::string& stored);
// The canonical absolute form of `p` (lexically normalised if it does not exist).
std::string absolute(const std::string& p);
// True when `p` lies inside folder `dir` (both made absolute first).
bool is_within(const std::string& p, const std::string& dir);
// The folder part of a file path ("." when none).
std::string dirname(const std::string& p);

}  // namespace squawk::paths
