#include "rag/corpus.h"

#include "core/files.h"
#include "core/text.h"

namespace squawk::rag {

namespace {

constexpr const char* kHeader = "id\tsetup\tutterance\texpected\tcategory";

// Splits on a multi-character separator, trimming each part.
std::vector<std::string> split_on(const std::string& s, const std::string& sep) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t at = s.find(sep, start);
    const auto part = text::trim(std::string_view(s).substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (!part.empty()) out.emplace_back(part);
    if (at == std::string::npos) break;
    start = at + sep.size();
  }
  return out;
}

}  // namespace

std::vector<std::vector<std::string>> CorpusCase::alternatives() const {
  std::vector<std::vector<std::string>> alts;
  for (const auto& alt : split_on(expected, "||")) alts.push_back(split_on(alt, " ; "));
  return alts;
}

std::string command_word(const std::string& command) {
  const auto words = text::split_ws(command);
  return words.empty() ? std::string() : text::upper(words.front());
}

Result<std::vector<CorpusCase>> read_corpus(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string data, files::read(path));
  return parse_corpus(data, path);
}

Result<std::vector<CorpusCase>> parse_corpus(const std::string& data, const std::string& path) {
  std::vector<CorpusCase> cases;
  const auto lines = text::split(data, '\n');
  for (size_t i = 0; i < lines.size(); ++i) {
    std::string line = lines[i];
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (i == 0) {
      if (line != kHeader)
        return Status::corruption(path + ":1: header is not '" + std::string(kHeader) +
                                  "' (tab-separated)");
      continue;
    }
    if (text::trim(line).empty()) continue;
    auto cols = text::split(line, '\t');
    if (cols.size() != 5)
      return Status::corruption(path + ":" + std::to_string(i + 1) + ": expected 5 tab-separated columns, got " +
                                std::to_string(cols.size()));
    cases.push_back({cols[0], cols[1], cols[2], cols[3], cols[4]});
  }
  return cases;
}

}  // namespace squawk::rag
