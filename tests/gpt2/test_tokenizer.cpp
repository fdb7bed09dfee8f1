// GPT-2 byte-level BPE: pre-tokenisation per GPT-2's pattern, merges by rank,
// Hugging Face files, round trips.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "core/rng.h"
#include "gpt2/bpe.h"

using namespace squawk;
using namespace squawk::gpt2;

namespace {

std::vector<std::string> pieces(std::string_view s) {
  std::vector<std::string> out;
  for (auto p : pretokenize(s)) out.emplace_back(p);
  return out;
}

using V = std::vector<std::string>;

Tokenizer hand_made(const std::string& merges) {
  // Byte tokens plus every merge result used below.
  auto t = Tokenizer::bytes_only();
  std::string json = t.vocab_json();
  json.pop_back();  // "\n"
  json.pop_back();  // "}"
  json += ", \"ab\": 300, \"bc\": 301, \"abab\": 302, \"aa\": 303, \"abc\": 304}";
  auto r = Tokenizer::from_hf(json, merges);
  REQUIRE_MESSAGE(r.is_ok(), r.status().message());
  return std::move(r).value();
}

}  // namespace

TEST_CASE("byte alphabet is GPT-2's bytes_to_unicode") {
  CHECK(byte_to_codepoint('A') == 'A');
  CHECK(byte_to_codepoint(' ') == 0x120);   // 'Ġ'
  CHECK(byte_to_codepoint('\n') == 0x10A);  // 'Ċ'
  CHECK(byte_to_codepoint(0) == 0x100);
  CHECK(byte_to_codepoint(173) == 0x143);   // the soft hyphen is the last shifted byte
  CHECK(byte_to_codepoint(0xFF) == 0xFF);
  for (int b = 0; b < 256; ++b) CHECK(codepoint_to_byte(byte_to_codepoint(static_cast<uint8_t>(b))) == b);
  CHECK(codepoint_to_byte(0x20) == -1);
}

TEST_CASE("pre-tokenisation follows GPT-2's pattern") {
  CHECK(pieces("Hello world") == V{"Hello", " world"});
  CHECK(pieces("I'm here, aren't we?") == V{"I", "'m", " here", ",", " aren", "'t", " we", "?"});
  CHECK(pieces("'s'S") == V{"'s", "'", "S"});
  CHECK(pieces("  hi") == V{" ", " hi"});
  CHECK(pieces("a\n\nb") == V{"a", "\n", "\n", "b"});
  CHECK(pieces("end   ") == V{"end", "   "});
  CHECK(pieces("x \ty") == V{"x", " ", "\t", "y"});
  CHECK(pieces("FL350 3.14 1,000") == V{"FL", "350", " 3", ".", "14", " 1", ",", "000"});
  CHECK(pieces("hello!!! ?") == V{"hello", "!!!", " ?"});
  CHECK(pieces("h\xc3\xa9llo w\xc3\xb6rld") == V{"h\xc3\xa9llo", " w\xc3\xb6rld"});
  CHECK(pieces("\xe6\x97\xa5\xe6\x9c\xac \xe3\x83\x86") == V{"\xe6\x97\xa5\xe6\x9c\xac", " \xe3\x83\x86"});
  CHECK(pieces("x\xc2\xb2") == V{"x", "\xc2\xb2"});  // superscript two is a number (No)
  CHECK(pieces("a\xc2\xa0" "b") == V{"a", "\xc2\xa0", "b"});  // no-break space is white space
  CHECK(pieces("\xff\xfe" "ab") == V{"\xff\xfe", "ab"});      // invalid UTF-8 bytes are "other"
  CHECK(pieces("").empty());
}

TEST_CASE("letters added in Unicode 15.0 and 15.1 are letters: \\p{L} then 's, as GPT-2's encoder splits") {
  // U+11F04 KAWI LETTER A (15.0), U+2EBF0 and U+2EE5D (CJK Extension I, 15.1).
  CHECK(pieces("\xf0\x91\xbc\x84's") == V{"\xf0\x91\xbc\x84", "'s"});
  CHECK(pieces("\xf0\xae\xaf\xb0\xf0\xae\xb9\x9d's") == V{"\xf0\xae\xaf\xb0\xf0\xae\xb9\x9d", "'s"});
  // Still unassigned in 15.1 (U+2EE5E): "other", so the apostrophe joins it.
  CHECK(pieces("\xf0\xae\xb9\x9e's") == V{"\xf0\xae\xb9\x9e'", "s"});
}

TEST_CASE("merges apply lowest rank first, all occurrences, left to right") {
  // "b c" outranks "a b": abc -> a + bc.
  Tokenizer t = hand_made("#version: 0.2\nb c\na b\n");
  const int a = *t.encode("a")->begin(), b = *t.encode("b")->begin();
  CHECK(*t.encode("abc") == std::vector<int>{a, 301});
  CHECK(*t.encode("abab") == std::vector<int>{300, 300});
  // With "ab ab" ranked, the two ab merge further.
  Tokenizer t2 = hand_made("a b\nab ab\n");
  CHECK(*t2.encode("ababab") == std::vector<int>{302, 300});
  // Overlapping pairs merge left to right.
  Tokenizer t3 = hand_made("a a\n");
  CHECK(*t3.encode("aaa") == std::vector<int>{303, a});
  CHECK(*t3.encode("ba") == std::vector<int>{b, a});
}

TEST_CASE("a Hugging Face vocab.json / merges.txt pair loads and encodes") {
  auto t = Tokenizer::load(SQUAWK_TEST_DATA "/gpt2_vocab");
  REQUIRE_MESSAGE(t.is_ok(), t.status().message());
  CHECK(t->vocab_size() == 267);
  CHECK(t->num_merges() == 10);
  CHECK(t->eot() == 266);
  // " the" -> Ġt + he -> Ġthe (ranks 0, 1, 2).
  CHECK(*t->encode(" the") == std::vector<int>{258});
  CHECK(*t->encode("the an") == std::vector<int>{83, 257, 265});  // t=83 in GPT-2's byte order
  CHECK(*t->decode(std::vector<int>{258, 265, 266}) == " the an<|endoftext|>");
  CHECK_FALSE(t->decode(std::vector<int>{267}).is_ok());
  CHECK_FALSE(t->decode(std::vector<int>{-1}).is_ok());
  // Saving writes the same vocabulary back.
  auto again = Tokenizer::from_hf(t->vocab_json(), t->merges_txt());
  REQUIRE(again.is_ok());
  CHECK(*again->encode("the answer is there") == *t->encode("the answer is there"));
}

TEST_CASE("bad tokenizer files are clear errors") {
  auto err = [](const std::string& vocab, const std::string& merges) {
    auto r = Tokenizer::from_hf(vocab, merges);
    REQUIRE_FALSE(r.is_ok());
    return r.status().message();
  };
  CHECK(err("{not json", "").find("not valid JSON") != std::string::npos);
  CHECK(err("[1, 2]", "").find("object") != std::string::npos);
  CHECK(err("{\"a\": -1}", "").find("not an integer") != std::string::npos);
  CHECK(err("{\"a\": 0, \"b\": 0}", "").find("used twice") != std::string::npos);
  CHECK(err("{\" \": 0}", "").find("outside GPT-2's byte alphabet") != std::string::npos);
  CHECK(err("{\"a\": 0, \"b\": 1}", "a b\n").find("line 1") != std::string::npos);
  CHECK(err("{\"a\": 0, \"b\": 1, \"ab\": 2}", "#version: 0.2\na  b\n").find("line 2") != std::string::npos);
  // A vocabulary without some byte cannot encode it.
  auto small = Tokenizer::from_hf("{\"a\": 0}", "");
  REQUIRE(small.is_ok());
  CHECK_FALSE(small->encode("b").is_ok());
}

TEST_CASE("encode then decode returns the input for arbitrary bytes and UTF-8") {
  const Tokenizer bytes = Tokenizer::bytes_only();
  const Tokenizer trained = Tokenizer::train(
      "the aircraft climbs to flight level 350; the aircraft turns left heading 270. "
      "KLM204 descend to 3000 ft, reduce speed to 250 kt. Direct to SPY, then ARTIP.",
      60);
  CHECK(trained.num_merges() == 60);
  CHECK(trained.vocab_size() == 256 + 60 + 1);
  Rng rng(2024);
  for (int iter = 0; iter < 300; ++iter) {
    std::string s;
    const int n = static_cast<int>(rng.uniform_int(0, 40));
    for (int i = 0; i < n; ++i) {
      const double u = rng.uniform();
      if (u < 0.3) {
        s.push_back(static_cast<char>(rng.uniform_int(0, 255)));  // any byte
      } else if (u < 0.6) {
        s.append(" the aircraft"[rng.uniform_int(0, 12)] == ' ' ? " " : "the ");
      } else {  // a valid UTF-8 code point, any plane
        uint32_t cp = static_cast<uint32_t>(rng.uniform_int(1, 0x10FFFF));
        if (cp >= 0xD800 && cp <= 0xDFFF) cp = 'x';
        std::string u8;
        if (cp < 0x80) u8 = std::string(1, static_cast<char>(cp));
        else if (cp < 0x800) u8 = {static_cast<char>(0xC0 | (cp >> 6)), static_cast<char>(0x80 | (cp & 0x3F))};
        else if (cp < 0x10000) u8 = {static_cast<char>(0xE0 | (cp >> 12)), static_cast<char>(0x80 | ((cp >> 6) & 0x3F)), static_cast<char>(0x80 | (cp & 0x3F))};
        else u8 = {static_cast<char>(0xF0 | (cp >> 18)), static_cast<char>(0x80 | ((cp >> 12) & 0x3F)), static_cast<char>(0x80 | ((cp >> 6) & 0x3F)), static_cast<char>(0x80 | (cp & 0x3F))};
        s += u8;
      }
    }
    for (const Tokenizer* t : {&bytes, &trained}) {
      auto ids = t->encode(s);
      REQUIRE(ids.is_ok());
      auto back = t->decode(*ids);
      REQUIRE(back.is_ok());
      CHECK(*back == s);
    }
    std::string joined;
    for (auto p : pretokenize(s)) joined.append(p);
    CHECK(joined == s);
  }
  // The trained merges compress text like their corpus.
  CHECK(trained.encode("the aircraft climbs")->size() < bytes.encode("the aircraft climbs")->size() / 2);
}
