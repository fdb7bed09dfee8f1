// TrafScript tokenizer against BlueSky's own argument regex, run in Python.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "command/line.h"
#include "core/rng.h"

using namespace squawk;
using namespace squawk::command;

TEST_CASE("separators: whitespace and at most one comma; empty = omitted") {
  using V = std::vector<std::string>;
  CHECK(tokenize("A,B") == V{"A", "B"});
  CHECK(tokenize("A B") == V{"A", "B"});
  CHECK(tokenize("A , B") == V{"A", "B"});
  CHECK(tokenize("\tA\t,\tB  ") == V{"A", "B"});
  CHECK(tokenize("a,,b") == V{"a", "", "b"});
  CHECK(tokenize("a , , b") == V{"a", "", "b"});
  CHECK(tokenize("ECHO 'hello world', x") == V{"ECHO", "hello world", "x"});
  CHECK(tokenize("N52'35'06.44\" E003'24'51.04\"") == V{"N52'35'06.44\"", "E003'24'51.04\""});
  ArgReader r("x,,y");
  CHECK(r.next() == "x");
  CHECK(r.next_omitted());
  CHECK(r.next().empty());
  CHECK_FALSE(r.next_omitted());
  CHECK(r.next() == "y");
  CHECK(r.at_end());
  CHECK(split_commands("A;B; ;C ") == V{"A", "B", "C"});
}

namespace {

// BlueSky's argparser.re_getarg applied until the text is used up.
std::vector<std::vector<std::string>> python_tokenize(const std::vector<std::string>& lines) {
  const char* script = "/tmp/squawk_command_tok.py";
  FILE* f = std::fopen(script, "w");
  if (!f) return {};
  std::fputs(
      "import re,sys\n"
      "r=re.compile(r'\\s*[\\'\"]?((?<=[\\'\"])[^\\'\"]*|(?<![\\'\"])[^\\s,]*)[\\'\"]?\\s*,?\\s*(.*)')\n"
      "for line in sys.stdin.read().split('\\n')[:-1]:\n"
      "  s=bytes.fromhex(line).decode('latin-1'); out=[]\n"
      "  s=s.lstrip(' \\t\\n\\r\\f\\v')\n"
      "  while s:\n"
      "    a,s=r.match(s).groups(); out.append(a.encode('latin-1').hex())\n"
      "  print(' '.join(['.'+x for x in out]))\n",
      f);
  std::fclose(f);
  const std::string in_path = "/tmp/squawk_command_tok.in";
  FILE* in = std::fopen(in_path.c_str(), "w");
  for (const auto& l : lines) {
    for (unsigned char c : l) std::fprintf(in, "%02x", c);
    std::fputc('\n', in);
  }
  std::fclose(in);
  FILE* p = popen(("/usr/bin/python3 " + std::string(script) + " < " + in_path).c_str(), "r");
  if (!p) return {};
  std::vector<std::vector<std::string>> out;
  char buf[1 << 16];
  while (std::fgets(buf, sizeof buf, p)) {
    std::vector<std::string> toks;
    std::string line(buf);
    if (!line.empty() && line.back() == '\n') line.pop_back();
    size_t i = 0;
    while (i < line.size()) {
      size_t j = line.find(' ', i);
      if (j == std::string::npos) j = line.size();
      std::string hex = line.substr(i + 1, j - i - 1), tok;
      for (size_t k = 0; k + 1 < hex.size(); k += 2) tok.push_back(static_cast<char>(std::stoi(hex.substr(k, 2), nullptr, 16)));
      toks.push_back(tok);
      i = j + 1;
    }
    out.push_back(toks);
  }
  pclose(p);
  return out;
}

}  // namespace

TEST_CASE("tokenizer matches BlueSky's regex on random lines") {
  if (!std::fopen("/usr/bin/python3", "r")) {
    MESSAGE("skipped: /usr/bin/python3 not found");
    return;
  }
  Rng rng(7);
  const char alphabet[] = {'A', 'b', '1', '.', ' ', ' ', ',', ',', '\t', '\'', '"', '-', 'M'};
  std::vector<std::string> lines;
  for (int n = 0; n < 3000; ++n) {
    std::string s;
    const int len = static_cast<int>(rng.uniform_int(0, 16));
    for (int k = 0; k < len; ++k) s.push_back(alphabet[rng.uniform_int(0, sizeof alphabet - 1)]);
    lines.push_back(s);
  }
  auto want = python_tokenize(lines);
  REQUIRE(want.size() == lines.size());
  int mismatches = 0;
  for (size_t n = 0; n < lines.size(); ++n) {
    if (tokenize(lines[n]) != want[n] && ++mismatches <= 5) MESSAGE("line [" << lines[n] << "]");
  }
  CHECK(mismatches == 0);
}
