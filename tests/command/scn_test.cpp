// .scn reader: BlueSky's readscn rules, and a comparison with a Python
// re-implementation of readscn over BlueSky's 324 shipped scenario files.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "command/scn.h"
#include "core/text.h"

using namespace squawk;
using namespace squawk::command;
namespace fs = std::filesystem;

TEST_CASE("scn: line endings, comments, continuation, timestamps, stable sort") {
  const std::string text =
      "# header comment line\r\n"
      "00:00:10.00>ECHO second\r\n"
      "0:00:00.00>CRE KL204 B744 52 4 90 FL100 250   # trailing comment\r"
      "00:00:00 > ECHO third-at-zero\n"
      "short\n"
      "00:00:05.00>POLY A 1 2 \\\n"
      "   3 4 5 6 7 8\n"
      "]00:00:00.00>ECHO broken\n"
      "0:00:01:99>ECHO four fields\n"
      "00:00:10.00>ECHO after second";
  ScnFile f = parse_scn(text);
  REQUIRE(f.entries.size() == 6);
  CHECK(f.entries[0].command == "CRE KL204 B744 52 4 90 FL100 250");
  CHECK(f.entries[0].line == 3);
  CHECK(f.entries[1].command == "ECHO third-at-zero");
  CHECK(f.entries[2].time == 1.0);
  CHECK(f.entries[3].command == "POLY A 1 2 3 4 5 6 7 8");
  CHECK(f.entries[3].time == 5.0);
  CHECK(f.entries[4].command == "ECHO second");
  CHECK(f.entries[5].command == "ECHO after second");
  REQUIRE(f.rejected.size() == 1);
  CHECK(f.rejected[0].line == 8);
}

TEST_CASE("scn: all BlueSky scenario files parse like BlueSky's readscn" * doctest::test_suite("shared")) {
  const fs::path dir = fs::path(SQUAWK_SHARED_DIR) / "bluesky" / "scenario";
  if (!fs::is_directory(dir)) {
    MESSAGE("skipped: " << dir.string() << " not found (BlueSky data is optional)");
    return;
  }
  if (!fs::exists("/usr/bin/python3")) {
    MESSAGE("skipped: /usr/bin/python3 not found");
    return;
  }
  const char* script = "/tmp/squawk_command_readscn.py";
  FILE* f = std::fopen(script, "w");
  REQUIRE(f);
  // readscn from BlueSky's stack/simstack.py, restated: one output line per
  // entry, "time|command", after a "FILE path" line.
  std::fputs(
      "import sys,os\n"
      "for root,_,names in sorted(os.walk(sys.argv[1])):\n"
      "  for n in sorted(names):\n"
      "    p=os.path.join(root,n); print('FILE '+p); prev=''; out=[]\n"
      "    for line in open(p,encoding='latin-1'):\n"
      "      line=line.strip(' \\t\\n\\r\\x0b\\x0c')\n"
      "      if len(line)<10 or line[0]=='#': continue\n"
      "      line=prev+line\n"
      "      if line[-1]=='\\\\':\n"
      "        prev=line[:-1].strip(' \\t\\n\\r\\x0b\\x0c')+' '; continue\n"
      "      prev=''\n"
      "      try:\n"
      "        line=line.split('#')[0].strip(' \\t\\n\\r\\x0b\\x0c'); i=line.index('>')\n"
      "        t=line[:i].strip().split(':')\n"
      "        out.append((int(t[0])*3600.0+int(t[1])*60.0+float(t[2]),line[i+1:].strip(' \\t\\n\\r\\x0b\\x0c')))\n"
      "      except (ValueError,IndexError): pass\n"
      "    for t,c in sorted(out,key=lambda x:x[0]): print('%.6f|%s'%(t,c))\n",
      f);
  std::fclose(f);
  FILE* p = popen(("/usr/bin/python3 " + std::string(script) + " '" + dir.string() + "'").c_str(), "r");
  REQUIRE(p);
  std::string all;
  char buf[1 << 16];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) all.append(buf, n);
  pclose(p);

  int files = 0, entries = 0, mismatched_files = 0;
  std::vector<std::string> want;
  std::string current;
  auto compare = [&]() {
    if (current.empty()) return;
    ++files;
    auto got = read_scn(current);
    REQUIRE(got);
    bool same = got->entries.size() == want.size();
    for (size_t k = 0; same && k < want.size(); ++k) {
      char t[64];
      std::snprintf(t, sizeof t, "%.6f|", got->entries[k].time);
      same = want[k] == std::string(t) + got->entries[k].command;
      if (!same) MESSAGE(current << ": got [" << t << got->entries[k].command << "] want [" << want[k] << "]");
    }
    entries += static_cast<int>(want.size());
    if (!same) ++mismatched_files;
    want.clear();
  };
  for (const auto& line : text::split(all, '\n')) {
    if (line.rfind("FILE ", 0) == 0) {
      compare();
      current = line.substr(5);
    } else if (!line.empty()) {
      want.push_back(line);
    }
  }
  compare();
  MESSAGE(files << " files, " << entries << " entries compared");
  CHECK(files == 325);
  CHECK(entries > 90000);
  CHECK(mismatched_files == 0);
}
