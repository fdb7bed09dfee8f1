#include "rag/notes.h"

#include "core/files.h"
#include "core/text.h"

namespace squawk::rag {

Result<std::vector<Document>> read_notes(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string data, files::read(path));
  std::vector<Document> notes;
  const auto lines = text::split(data, '\n');
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto line = text::trim(lines[i]);
    if (line.empty() || line.front() == '#') continue;
    const auto colon = line.find(':');
    const auto name = colon == std::string_view::npos ? std::string_view() : text::trim(line.substr(0, colon));
    if (name.empty() || name.find(' ') != std::string_view::npos)
      return Status::corruption(path + ":" + std::to_string(i + 1) +
                                ": expected `NAME: text` (a command name, a colon, then the note)");
    notes.push_back({text::upper(name), std::string(text::trim(line.substr(colon + 1)))});
  }
  return notes;
}

}  // namespace squawk::rag
