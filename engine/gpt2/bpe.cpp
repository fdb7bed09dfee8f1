#include "gpt2/bpe.h"

#include <algorithm>
#include <array>
#include <map>

#include <nlohmann/json.hpp>

#include "core/files.h"
#include "core/text.h"

namespace squawk::gpt2 {

namespace {

struct CodeRange {
  uint32_t lo, hi;
};
#include "gpt2/unicode_classes.inc"

template <size_t N>
bool in_ranges(const CodeRange (&r)[N], uint32_t cp) {
  auto it = std::upper_bound(std::begin(r), std::end(r), cp,
                             [](uint32_t v, const CodeRange& x) { return v < x.lo; });
  return it != std::begin(r) && cp <= std::prev(it)->hi;
}

bool is_white_space(uint32_t cp) {
  return (cp >= 0x9 && cp <= 0xD) || cp == 0x20 || cp == 0x85 || cp == 0xA0 || cp == 0x1680 ||
         (cp >= 0x2000 && cp <= 0x200A) || cp == 0x2028 || cp == 0x2029 || cp == 0x202F ||
         cp == 0x205F || cp == 0x3000;
}

enum class Cls : uint8_t { kLetter, kNumber, kSpace, kOther };

struct Char {
  uint32_t cp;  // 0xFFFFFFFF for a byte outside valid UTF-8
  size_t off, len;
  Cls cls;
};

constexpr uint32_t kInvalid = 0xFFFFFFFFu;

// Decodes one UTF-8 character at s[i]; invalid sequences yield one byte.
Char decode_utf8(std::string_view s, size_t i) {
  const auto u = [&](size_t k) { return static_cast<uint8_t>(s[k]); };
  const uint8_t c = u(i);
  size_t len = 0;
  uint32_t cp = 0, min = 0;
  if (c < 0x80) return {c, i, 1, Cls::kOther};
  if ((c & 0xE0) == 0xC0) len = 2, cp = c & 0x1F, min = 0x80;
  else if ((c & 0xF0) == 0xE0) len = 3, cp = c & 0x0F, min = 0x800;
  else if ((c & 0xF8) == 0xF0) len = 4, cp = c & 0x07, min = 0x10000;
  else return {kInvalid, i, 1, Cls::kOther};
  if (i + len > s.size()) return {kInvalid, i, 1, Cls::kOther};
  for (size_t k = 1; k < len; ++k) {
    if ((u(i + k) & 0xC0) != 0x80) return {kInvalid, i, 1, Cls::kOther};
    cp = (cp << 6) | (u(i + k) & 0x3F);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
    return {kInvalid, i, 1, Cls::kOther};
  return {cp, i, len, Cls::kOther};
}

Cls classify(uint32_t cp) {
  if (cp == kInvalid) return Cls::kOther;
  if (is_white_space(cp)) return Cls::kSpace;
  if (in_ranges(kLetterRanges, cp)) return Cls::kLetter;
  if (in_ranges(kNumberRanges, cp)) return Cls::kNumber;
  return Cls::kOther;
}

struct ByteTable {
  std::array<uint32_t, 256> to_cp{};
  std::map<uint32_t, int> to_byte;
  std::array<uint8_t, 256> order{};  // id -> byte, GPT-2's id order of the byte tokens
  ByteTable() {
    int n = 0, next = 0;
    auto printable = [](int b) {
      return (b >= 33 && b <= 126) || (b >= 161 && b <= 172) || (b >= 174 && b <= 255);
    };
    for (int b = 0; b < 256; ++b)
      if (printable(b)) to_cp[b] = static_cast<uint32_t>(b), order[next++] = static_cast<uint8_t>(b);
    for (int b = 0; b < 256; ++b)
      if (!printable(b)) to_cp[b] = 256u + static_cast<uint32_t>(n++), order[next++] = static_cast<uint8_t>(b);
    for (int b = 0; b < 256; ++b) to_byte[to_cp[b]] = b;
  }
};

const ByteTable& table() {
  static const ByteTable t;
  return t;
}

void append_utf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out.push_back(static_cast<char>(cp));
  } else if (cp < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (cp >> 6)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xE0 | (cp >> 12)));
    out.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (cp & 0x3F)));
  }
}

// GPT-2 alphabet text -> raw bytes; error when a character stands for no byte.
Result<std::string> unmap(std::string_view token) {
  std::string out;
  for (size_t i = 0; i < token.size();) {
    const Char c = decode_utf8(token, i);
    const int b = c.cp == kInvalid ? -1 : codepoint_to_byte(c.cp);
    if (b < 0)
      return Status::corruption("token " + text::quoted(token) +
                                " has a character outside GPT-2's byte alphabet");
    out.push_back(static_cast<char>(b));
    i += c.len;
  }
  return out;
}

std::string map_bytes(std::string_view raw) {
  std::string out;
  for (char c : raw) append_utf8(out, byte_to_codepoint(static_cast<uint8_t>(c)));
  return out;
}

constexpr char kEot[] = "<|endoftext|>";

uint64_t pair_key(int a, int b) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

}  // namespace

uint32_t byte_to_codepoint(uint8_t b) { return table().to_cp[b]; }

int codepoint_to_byte(uint32_t cp) {
  auto it = table().to_byte.find(cp);
  return it == table().to_byte.end() ? -1 : it->second;
}

std::vector<std::string_view> pretokenize(std::string_view text) {
  std::vector<Char> cs;
  for (size_t i = 0; i < text.size();) {
    Char c = decode_utf8(text, i);
    c.cls = classify(c.cp);
    cs.push_back(c);
    i += c.len;
  }
  std::vector<std::string_view> out;
  const size_t n = cs.size();
  auto emit = [&](size_t a, size_t b) {
    const size_t from = cs[a].off, to = b < n ? cs[b].off : text.size();
    out.push_back(text.substr(from, to - from));
  };
  auto run_end = [&](size_t j, Cls cls) {
    while (j < n && cs[j].cls == cls) ++j;
    return j;
  };
  static const char* const kContractions[] = {"s", "t", "re", "ve", "m", "ll", "d"};
  size_t i = 0;
  while (i < n) {
    if (cs[i].cp == '\'') {
      bool matched = false;
      for (const char* suf : kContractions) {
        size_t k = 0;
        while (suf[k] && i + 1 + k < n && cs[i + 1 + k].cp == static_cast<uint8_t>(suf[k])) ++k;
        if (suf[k] == '\0') {
          emit(i, i + 1 + k);
          i += 1 + k;
          matched = true;
          break;
        }
      }
      if (matched) continue;
    }
    // " ?\p{L}+", " ?\p{N}+", " ?[^\s\p{L}\p{N}]+", in this order.
    const size_t body = (cs[i].cp == ' ' && i + 1 < n && cs[i + 1].cls != Cls::kSpace) ? i + 1 : i;
    if (cs[body].cls != Cls::kSpace) {
      const size_t e = run_end(body, cs[body].cls);
      emit(i, e);
      i = e;
      continue;
    }
    // "\s+(?!\S)" leaves the last white space to the next piece, else "\s+".
    const size_t e = run_end(i, Cls::kSpace);
    const size_t stop = (e < n && e - i >= 2) ? e - 1 : e;
    emit(i, stop);
    i = stop;
  }
  return out;
}

void Tokenizer::add_merge(int a, int b, int merged) {
  if (rank_.emplace(pair_key(a, b), static_cast<int>(merges_.size())).second)
    merges_.push_back({a, b, merged});
}

Result<Tokenizer> Tokenizer::from_hf(const std::string& vocab_json, const std::string& merges_txt) {
  const auto j = nlohmann::json::parse(vocab_json, nullptr, false);
  if (j.is_discarded()) return Status::corruption("vocab.json: not valid JSON");
  if (!j.is_object() || j.empty())
    return Status::corruption("vocab.json: expected a non-empty object of token -> id");
  Tokenizer t;
  std::fill(std::begin(t.byte_ids_), std::end(t.byte_ids_), -1);
  for (const auto& [tok, idv] : j.items()) {
    if (!idv.is_number_unsigned() || idv.get<uint64_t>() >= 1000000)
      return Status::corruption("vocab.json: id of " + text::quoted(tok) +
                                " is not an integer in 0..999999");
    const int id = static_cast<int>(idv.get<uint64_t>());
    auto raw = unmap(tok);
    if (!raw) return raw.status().with_context("vocab.json");
    if (static_cast<size_t>(id) >= t.token_bytes_.size()) {
      t.token_bytes_.resize(id + 1);
      t.used_.resize(id + 1, false);
    }
    if (t.used_[id]) return Status::corruption("vocab.json: id " + std::to_string(id) + " is used twice");
    if (t.ids_.count(*raw)) return Status::corruption("vocab.json: token " + text::quoted(tok) + " appears twice");
    t.used_[id] = true;
    t.token_bytes_[id] = *raw;
    t.ids_[*raw] = id;
    if (raw->size() == 1) t.byte_ids_[static_cast<uint8_t>((*raw)[0])] = id;
    if (*raw == kEot) t.eot_ = id;
  }
  const auto lines = text::split(merges_txt, '\n');
  for (size_t ln = 0; ln < lines.size(); ++ln) {
    std::string_view line = lines[ln];
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || (ln == 0 && line.rfind("#version", 0) == 0)) continue;
    const auto parts = text::split(line, ' ');
    const std::string where = "merges.txt line " + std::to_string(ln + 1) + ": ";
    if (parts.size() != 2 || parts[0].empty() || parts[1].empty())
      return Status::corruption(where + text::quoted(line) + " is not two tokens separated by one space");
    auto a = unmap(parts[0]);
    auto b = unmap(parts[1]);
    if (!a || !b) return Status::corruption(where + (a ? b : a).status().message());
    const auto ia = t.ids_.find(*a), ib = t.ids_.find(*b), im = t.ids_.find(*a + *b);
    if (ia == t.ids_.end() || ib == t.ids_.end() || im == t.ids_.end())
      return Status::corruption(where + "merge " + text::quoted(line) +
                                " uses or makes a token missing from vocab.json");
    t.add_merge(ia->second, ib->second, im->second);
  }
  return t;
}

Result<Tokenizer> Tokenizer::load(const std::string& dir) {
  SQUAWK_ASSIGN_OR_RETURN(std::string vocab, files::read(dir + "/vocab.json"));
  SQUAWK_ASSIGN_OR_RETURN(std::string merges, files::read(dir + "/merges.txt"));
  auto t = from_hf(vocab, merges);
  if (!t) return t.status().with_context(dir);
  return t;
}

Tokenizer Tokenizer::bytes_only() {
  Tokenizer t;
  t.token_bytes_.resize(257);
  t.used_.assign(257, true);
  for (int id = 0; id < 256; ++id) {
    const uint8_t b = table().order[id];
    t.token_bytes_[id] = std::string(1, static_cast<char>(b));
    t.ids_[t.token_bytes_[id]] = id;
    t.byte_ids_[b] = id;
  }
  t.token_bytes_[256] = kEot;
  t.ids_[kEot] = 256;
  t.eot_ = 256;
  return t;
}

Tokenizer Tokenizer::train(std::string_view corpus, int merges) {
  Tokenizer t = bytes_only();
  t.token_bytes_.pop_back();
  t.used_.pop_back();
  t.ids_.erase(kEot);
  std::map<std::string_view, long> counts;
  for (std::string_view piece : pretokenize(corpus)) ++counts[piece];
  std::vector<std::pair<std::vector<int>, long>> words;
  for (const auto& [piece, n] : counts) {
    std::vector<int> ids;
    for (char c : piece) ids.push_back(t.byte_ids_[static_cast<uint8_t>(c)]);
    words.emplace_back(std::move(ids), n);
  }
  for (int m = 0; m < merges; ++m) {
    std::map<std::pair<int, int>, long> pairs;
    for (const auto& [ids, n] : words)
      for (size_t i = 0; i + 1 < ids.size(); ++i) pairs[{ids[i], ids[i + 1]}] += n;
    if (pairs.empty()) break;
    auto best = pairs.begin();
    for (auto it = pairs.begin(); it != pairs.end(); ++it)
      if (it->second > best->second) best = it;
    const auto [a, b] = best->first;
    const int id = static_cast<int>(t.token_bytes_.size());
    t.token_bytes_.push_back(t.token_bytes_[a] + t.token_bytes_[b]);
    t.used_.push_back(true);
    t.ids_[t.token_bytes_.back()] = id;
    t.add_merge(a, b, id);
    for (auto& [ids, n] : words) {
      std::vector<int> next;
      for (size_t i = 0; i < ids.size(); ++i) {
        if (i + 1 < ids.size() && ids[i] == a && ids[i + 1] == b) {
          next.push_back(id);
          ++i;
        } else {
          next.push_back(ids[i]);
        }
      }
      ids = std::move(next);
    }
  }
  t.eot_ = static_cast<int>(t.token_bytes_.size());
  t.token_bytes_.push_back(kEot);
  t.used_.push_back(true);
  t.ids_[kEot] = *t.eot_;
  return t;
}

void Tokenizer::bpe(std::vector<int>& ids) const {
  while (ids.size() > 1) {
    int best_rank = -1;
    for (size_t i = 0; i + 1 < ids.size(); ++i) {
      auto it = rank_.find(pair_key(ids[i], ids[i + 1]));
      if (it != rank_.end() && (best_rank < 0 || it->second < best_rank)) best_rank = it->second;
    }
    if (best_rank < 0) return;
    const Merge& m = merges_[best_rank];
    size_t w = 0;
    for (size_t i = 0; i < ids.size(); ++i) {
      if (i + 1 < ids.size() && ids[i] == m.a && ids[i + 1] == m.b) {
        ids[w++] = m.merged;
        ++i;
      } else {
        ids[w++] = ids[i];
      }
    }
    ids.resize(w);
  }
}

Result<std::vector<int>> Tokenizer::encode(std::string_view text) const {
  std::vector<int> out, ids;
  for (std::string_view piece : pretokenize(text)) {
    ids.clear();
    for (char c : piece) {
      const int id = byte_ids_[static_cast<uint8_t>(c)];
      if (id < 0)
        return Status::invalid("tokenizer: the vocabulary has no token for byte " +
                               std::to_string(static_cast<uint8_t>(c)));
      ids.push_back(id);
    }
    bpe(ids);
    out.insert(out.end(), ids.begin(), ids.end());
  }
  return out;
}

Result<std::string> Tokenizer::decode(std::span<const int> ids) const {
  std::string out;
  for (int id : ids) {
    if (id < 0 || id >= vocab_size() || !used_[id])
      return Status::invalid("tokenizer: id " + std::to_string(id) + " is not in the vocabulary of " +
                             std::to_string(vocab_size()));
    out.append(token_bytes_[id]);
  }
  return out;
}

std::string Tokenizer::vocab_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (size_t id = 0; id < token_bytes_.size(); ++id)
    if (used_[id]) j[map_bytes(token_bytes_[id])] = id;
  return j.dump() + "\n";
}

std::string Tokenizer::merges_txt() const {
  std::string out = "#version: 0.2\n";
  for (const Merge& m : merges_)
    out.append(map_bytes(token_bytes_[m.a])).append(" ").append(map_bytes(token_bytes_[m.b])).append("\n");
  return out;
}

Status Tokenizer::save(const std::string& dir) const {
  SQUAWK_RETURN_IF_ERROR(files::make_dirs(dir));
  SQUAWK_RETURN_IF_ERROR(files::write_atomic(dir + "/vocab.json", vocab_json()));
  return files::write_atomic(dir + "/merges.txt", merges_txt());
}

}  // namespace squawk::gpt2
