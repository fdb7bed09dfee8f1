// Recall@K of retrieval on a translator corpus.
//
// A case counts as a hit at K when, for at least one expected alternative,
// every command it uses (names folded to the registry's canonical names) is
// the command of one of the top-K documents retrieved for the utterance.
// ASK cases are counted apart (they expect no command), as are cases whose
// expected command the registry does not know.
#pragma once

#include <string>
#include <vector>

#include "rag/bm25.h"
#include "rag/corpus.h"

namespace squawk::rag {

struct RecallReport {
  size_t k = 5;
  size_t scored = 0;          // cases with a known expected command
  size_t hits_at_1 = 0;
  size_t hits_at_k = 0;
  size_t ask_cases = 0;       // skipped: expected ASK
  size_t unknown_cases = 0;   // skipped: expected command not in the registry
  std::vector<std::string> misses;  // "id: want X; got A B C"

  double recall_at_1() const { return scored ? double(hits_at_1) / double(scored) : 0.0; }
  double recall_at_k() const { return scored ? double(hits_at_k) / double(scored) : 0.0; }
};

RecallReport evaluate_recall(const Bm25Index& index, const std::vector<CorpusCase>& cases, size_t k);

}  // namespace squawk::rag
