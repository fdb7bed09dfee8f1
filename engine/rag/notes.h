// Extra retrieval notes: plain-text lines that teach retrieval the words
// people use for a command ("climb and maintain" -> ALT).
//
// Format: one note per line, `NAME: text`; blank lines and lines starting
// with `#` are ignored. NAME is a command name or alias. Errors name the file
// and line.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"
#include "rag/document.h"

namespace squawk::rag {

// The notes shipped with squawk, relative to squawk home.
inline constexpr const char* kDefaultNotes = "scripts/translate/phraseology.txt";

Result<std::vector<Document>> read_notes(const std::string& path);

}  // namespace squawk::rag
