// Extra retrieval notes: plain-text lines that teach retrieval the words
// people use for a command ("climb and maintain" -> ALT). squawk ships none:
// its words live in the grammar (scripts/translate/rules.lua); a notes file
// adds a user's own.
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

Result<std::vector<Document>> read_notes(const std::string& path);

}  // namespace squawk::rag
