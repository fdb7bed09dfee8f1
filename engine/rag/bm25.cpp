#include "rag/bm25.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "rag/tokenize.h"

namespace squawk::rag {

Bm25Index::Bm25Index(std::vector<Document> docs, double k1, double b)
    : docs_(std::move(docs)), k1_(k1), b_(b) {
  lengths_.reserve(docs_.size());
  double total = 0;
  for (size_t d = 0; d < docs_.size(); ++d) {
    const auto toks = tokenize(docs_[d].text);
    lengths_.push_back(toks.size());
    total += static_cast<double>(toks.size());
    std::map<std::string, int> counts;
    for (const auto& t : toks) ++counts[t];
    for (const auto& [t, n] : counts) postings_[t].emplace_back(d, n);
  }
  avg_len_ = docs_.empty() ? 0.0 : total / static_cast<double>(docs_.size());
}

std::vector<Hit> Bm25Index::search(std::string_view query, size_t k) const {
  std::vector<double> score(docs_.size(), 0.0);
  const double n_docs = static_cast<double>(docs_.size());
  for (const auto& t : tokenize(query)) {
    auto it = postings_.find(t);
    if (it == postings_.end()) continue;
    const double n_t = static_cast<double>(it->second.size());
    const double idf = std::log(1.0 + (n_docs - n_t + 0.5) / (n_t + 0.5));
    for (const auto& [d, f] : it->second) {
      const double norm = 1.0 - b_ + b_ * static_cast<double>(lengths_[d]) / avg_len_;
      score[d] += idf * f * (k1_ + 1.0) / (f + k1_ * norm);
    }
  }
  std::vector<Hit> hits;
  for (size_t d = 0; d < score.size(); ++d)
    if (score[d] > 0) hits.push_back({d, score[d]});
  std::stable_sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.score > b.score; });
  if (hits.size() > k) hits.resize(k);
  return hits;
}

}  // namespace squawk::rag
