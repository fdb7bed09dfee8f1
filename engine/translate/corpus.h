// Translation corpora (shared/corpora/*.tsv) and their evaluation.
//
// Contract: the cases are read by the one corpus reader, rag/corpus.h
// (rag::read_corpus / parse_corpus, errors naming file and line). evaluate() runs a translator on every case
// and scores it with score_case() into one of three outcomes:
//   right  the expected commands (or a question where ASK was expected);
//   asked  no command issued (a question, or nothing valid) where commands
//          were expected: safe, but not done;
//   wrong  a command issued that is not the expected one, or a command where
//          a question was expected: a wrong clearance.
// The report keeps per-case outcomes and per-category counts in first-seen
// order. format_report() prints a table in the style of the paper's Table 2
// (category, cases, right, asked, wrong, accuracy).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/status.h"
#include "rag/corpus.h"
#include "translate/translation.h"

namespace squawk::translate {

using rag::CorpusCase;
using rag::parse_corpus;
using rag::read_corpus;

struct CaseOutcome {
  // produced: the commands, the question, "error: ...", or the note when only what squawk
  // does not simulate was said
  std::string id, category, produced, expected;
  bool asked = false;    // no command was issued
  bool correct = false;  // right
  bool wrong() const { return !correct && !asked; }
};

struct CategoryScore {
  std::string category;
  int cases = 0;
  int correct = 0;  // right
  int asked = 0;
  int wrong = 0;
};

struct EvalReport {
  std::vector<CaseOutcome> outcomes;
  std::vector<CategoryScore> categories;
  int cases = 0;
  int correct = 0;  // right
  int asked = 0;
  int wrong = 0;
  double accuracy() const { return cases ? static_cast<double>(correct) / cases : 0.0; }
};

// A translator for one case: its own setup and utterance -> a Translation,
// or an error (for example a setup line it could not run).
using CaseTranslator = std::function<Result<Translation>(const CorpusCase&)>;

EvalReport evaluate(const std::vector<CorpusCase>& cases, const CaseTranslator& translate);
std::string format_report(const EvalReport& r, const std::string& title);

}  // namespace squawk::translate
