// The translator corpora (../shared/corpora/*.tsv): one case per row.
//
// Format (see the corpora README): a header `id setup utterance expected
// category`, tab-separated; `setup` and each expected alternative are
// TrafScript command lists joined by " ; "; alternatives are joined by
// " || "; `ASK` means the right answer is a question to the user.
#pragma once

#include <string>
#include <vector>

#include "core/status.h"

namespace squawk::rag {

struct CorpusCase {
  std::string id;
  std::string setup;      // TrafScript run before the utterance; may be empty
  std::string utterance;  // the English request
  std::string expected;   // as written in the file
  std::string category;

  bool is_ask() const { return expected == "ASK"; }
  // Each alternative as its list of commands, e.g. {{"ALT AC1 FL300"}}.
  std::vector<std::vector<std::string>> alternatives() const;
};

// Reads a corpus file. Errors name the file and line: a missing column, a
// header that is not the expected one. The one corpus reader of squawk
// (retrieval recall and translation accuracy both use it).
Result<std::vector<CorpusCase>> read_corpus(const std::string& path);
// Parses corpus text; `name` stands for the file in error messages.
Result<std::vector<CorpusCase>> parse_corpus(const std::string& tsv, const std::string& name);

// The command name of one TrafScript command: its first word, upper case.
std::string command_word(const std::string& command);

}  // namespace squawk::rag
