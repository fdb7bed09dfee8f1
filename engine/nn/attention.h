// Causal multi-head self-attention with a shared prefix, forward and backward.
//
// Shape legend: B sequences, T positions per sequence (the batch part), P
// prefix positions every sequence attends to first, C channels, NH heads,
// hs = C / NH head size. Rows are positions; buffers are float32 row-major.
//
// Row layout of qkv [R,3C] and out [R,C]: when the prefix is inline, its P
// rows come first and attend causally among themselves; then B blocks of T
// rows, block b holding sequence b. Without an inline prefix, R = B*T and the
// prefix keys/values come from k_ext, v_ext [P,C] (a cache); P may be 0.
// Each qkv row is [q | k | v], head h using columns h*hs .. h*hs+hs-1 of each.
// Query t of a sequence sees the P prefix keys and its own keys 0..t.
//
// Probabilities (att, optional in forward, needed by backward) are stored as
// [NH,P,P] for the inline prefix followed by [B,NH,T,P+T] for the sequences
// (prefix columns first); attention_probs_size() gives the total.
#pragma once

#include <cstddef>
#include <span>

namespace squawk::nn {

struct AttentionShape {
  int B = 1, T = 0, C = 0, NH = 1;
  int P = 0;                   // prefix length
  bool inline_prefix = false;  // prefix rows lead qkv/out (else k_ext/v_ext)
  int rows() const { return (inline_prefix ? P : 0) + B * T; }
};

size_t attention_probs_size(const AttentionShape& s);

// k_ext, v_ext: [P,C] with row stride ext_stride (ignored when inline or P = 0).
void attention_forward(float* out, float* att, const float* qkv, const float* k_ext,
                       const float* v_ext, int ext_stride, const AttentionShape& s);

// Accumulates dqkv [R,3C] from dout [R,C] and the forward's att. Gradients of
// an inline prefix collect the contributions of every sequence. An external
// prefix is treated as constant (no gradient).
void attention_backward(float* dqkv, const float* dout, const float* att, const float* qkv,
                        const float* k_ext, const float* v_ext, int ext_stride,
                        const AttentionShape& s);

// The same attention for a subset of the queries: rows[q] (q < Q) names a row
// of a sequence block of qkv (never an inline prefix row); out [Q,C] gets its
// output, att (optional) [Q,NH,P+T] its probabilities over the P prefix keys
// then the sequence's own keys (zero past the query's position). Keys and
// values of every row are read; GPT-2's last block needs only each sequence's
// last query, so this is its forward when nothing else reads the other rows.
size_t attention_rows_probs_size(const AttentionShape& s, int Q);
void attention_forward_rows(float* out, float* att, const float* qkv, const float* k_ext,
                            const float* v_ext, int ext_stride, const AttentionShape& s,
                            std::span<const int> rows);
// Accumulates dqkv [R,3C] from dout [Q,C] (the gradient of the rows' outputs)
// and attention_forward_rows' att: the query rows' q, and the keys and values
// they read (an inline prefix's included, an external prefix's not).
void attention_backward_rows(float* dqkv, const float* dout, const float* att, const float* qkv,
                             const float* k_ext, const float* v_ext, int ext_stride,
                             const AttentionShape& s, std::span<const int> rows);

// Plain-loop references of the full-query functions above, for tests.
void attention_forward_ref(float* out, float* att, const float* qkv, const float* k_ext,
                           const float* v_ext, int ext_stride, const AttentionShape& s);
void attention_backward_ref(float* dqkv, const float* dout, const float* att, const float* qkv,
                            const float* k_ext, const float* v_ext, int ext_stride,
                            const AttentionShape& s);

}  // namespace squawk::nn
