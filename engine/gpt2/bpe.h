// GPT-2's byte-level BPE tokenizer: pre-tokenisation, byte<->unicode
// alphabet, merges by rank; encode and decode.
//
// Text is bytes (UTF-8 expected but not required: a byte that does not start a
// valid UTF-8 sequence counts as one "other" character). Pre-tokenisation
// splits as GPT-2's pattern
//   's|'t|'re|'ve|'m|'ll|'d| ?\p{L}+| ?\p{N}+| ?[^\s\p{L}\p{N}]+|\s+(?!\S)|\s+
// with \p{L}, \p{N} the Unicode letter and number categories (Unicode 14 tables)
// and \s the White_Space property. Each piece's bytes map to GPT-2's 256-char
// alphabet (printable Latin-1 bytes stand for themselves, the rest shift to
// U+0100..), then the lowest-ranked adjacent pair in merges.txt merges, all its
// occurrences left to right, until no ranked pair remains. Decoding
// concatenates tokens' bytes, so decode(encode(s)) == s for every byte string.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/status.h"

namespace squawk::gpt2 {

// GPT-2's byte -> code point map (bytes_to_unicode) and its inverse (-1 when
// a code point stands for no byte).
uint32_t byte_to_codepoint(uint8_t b);
int codepoint_to_byte(uint32_t cp);

// Pieces of `text` per the pattern above, in order; they concatenate to text.
std::vector<std::string_view> pretokenize(std::string_view text);

class Tokenizer {
 public:
  // vocab.json (an object token -> id, tokens written in GPT-2's alphabet) and
  // merges.txt (optional "#version" line, then "A B" per line, rank = order).
  // Errors name the offending token or line.
  static Result<Tokenizer> from_hf(const std::string& vocab_json, const std::string& merges_txt);
  // DIR/vocab.json + DIR/merges.txt.
  static Result<Tokenizer> load(const std::string& dir);
  // The 256 byte tokens in GPT-2's id order (ids 0..255 as in GPT-2's own
  // vocabulary) plus <|endoftext|> = 256; no merges.
  static Tokenizer bytes_only();
  // Learns `merges` merges on `text` from bytes_only's alphabet: repeatedly the
  // most frequent adjacent pair within pre-tokenised pieces (ties: lowest ids).
  // New tokens get ids 256.. in order; <|endoftext|> comes last.
  static Tokenizer train(std::string_view text, int merges);

  // Error only when the vocabulary lacks a byte's token.
  Result<std::vector<int>> encode(std::string_view text) const;
  // Error on an id outside the vocabulary.
  Result<std::string> decode(std::span<const int> ids) const;

  int vocab_size() const { return static_cast<int>(token_bytes_.size()); }
  // Id of <|endoftext|>, when the vocabulary has it.
  std::optional<int> eot() const { return eot_; }
  size_t num_merges() const { return merges_.size(); }

  std::string vocab_json() const;
  std::string merges_txt() const;
  // Writes DIR/vocab.json and DIR/merges.txt.
  Status save(const std::string& dir) const;

 private:
  struct Merge {
    int a, b, merged;
  };
  void add_merge(int a, int b, int merged);
  void bpe(std::vector<int>& ids) const;

  std::vector<std::string> token_bytes_;  // id -> raw bytes ("" for unused ids)
  std::vector<bool> used_;                // id -> present in the vocabulary
  std::unordered_map<std::string, int> ids_;  // raw bytes -> id
  int byte_ids_[256];                     // byte -> id of its single-byte token, or -1
  std::vector<Merge> merges_;             // in rank order
  std::unordered_map<uint64_t, int> rank_;  // (a << 32 | b) -> rank
  std::optional<int> eot_;
};

}  // namespace squawk::gpt2
