#include "rag/bm25.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "rag/edit_distance.h"
#include "rag/tokenize.h"

namespace squawk::rag {

namespace {

}  // namespace

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

std::string Bm25Index::nearest_term(const std::string& word) const {
  if (word.size() < kMinFuzzyLength) return {};
  std::string best;
  for (const auto& [term, posting] : postings_) {
    if (term.size() + 1 < word.size() || term.size() > word.size() + 1) continue;
    if (edit_distance(word, term) == 1 && (best.empty() || term < best)) best = term;
  }
  return best;
}

std::vector<Hit> Bm25Index::search(std::string_view query, size_t k) const {
  std::vector<double> score(docs_.size(), 0.0);
  const double n_docs = static_cast<double>(docs_.size());
  for (const auto& t : tokenize(query)) {
    auto it = postings_.find(t);
    if (it == postings_.end()) it = postings_.find(nearest_term(t));
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
