// Bm25Index: Okapi BM25 ranking over a fixed set of documents.
//
// score(q, d) = sum over query terms t of
//   idf(t) * f(t,d) * (k1 + 1) / (f(t,d) + k1 * (1 - b + b * |d| / avgdl)),
//   idf(t) = ln(1 + (N - n(t) + 0.5) / (n(t) + 0.5)),
// with f the term count in d, |d| its length in tokens, N the number of
// documents and n(t) how many contain t. A query term counts once per
// occurrence. A query word of kMinFuzzyLength or more letters that no
// document contains stands for the indexed term one edit away (insertion,
// deletion, substitution or swap of neighbours; the alphabetically first when
// several), so typing slips ("tunr", "dleete") still retrieve. Ties keep
// document order, so results are deterministic.
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "rag/document.h"

namespace squawk::rag {

struct Hit {
  size_t doc = 0;      // index into documents()
  double score = 0.0;  // BM25 score, > 0
};

class Bm25Index {
 public:
  explicit Bm25Index(std::vector<Document> docs, double k1 = 1.2, double b = 0.75);

  // The best `k` documents with a positive score, best first.
  std::vector<Hit> search(std::string_view query, size_t k) const;
  const std::vector<Document>& documents() const { return docs_; }

 private:
  static constexpr size_t kMinFuzzyLength = 4;
  // The indexed term one edit from `word`, or "" (see above).
  std::string nearest_term(const std::string& word) const;

  std::vector<Document> docs_;
  double k1_, b_;
  double avg_len_ = 0.0;
  std::vector<size_t> lengths_;                                      // tokens per doc
  std::unordered_map<std::string, std::vector<std::pair<size_t, int>>> postings_;  // term -> (doc, count)
};

}  // namespace squawk::rag
