// The subcommand table: the single list `squawk --help` prints and dispatches.
#include "app/cli.h"
#include "app/subcommands.h"

namespace squawk::app {

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table = {
      {"run", "run FILE.lua [ARGS...]   run a Lua script (the script sees ARGS as `arg`)",
       "usage: squawk run FILE.lua [ARGS...] [--seed N] [--unsafe] [--out DIR]\n"
       "                 [--max-instructions N] [--navdata DIR]\n\n"
       "Runs a Lua script in squawk's sandbox. The script sees its arguments in the\n"
       "global table `arg` (arg[0] is the script path) and the engine as `squawk`.\n"
       "Flags squawk knows are taken wherever they stand; everything else goes to\n"
       "the script, and `--` passes the rest to the script untouched.\n\n"
       "  --seed N               seed of the engine RNG (math.random too); default 0\n"
       "  --unsafe               lift the sandbox: os, io, package.loadlib, C modules\n"
       "  --out DIR              the one folder the script may write files into\n"
       "  --max-instructions N   stop a script after N Lua VM instructions\n"
       "                         (default 500000000; 0 = no limit)\n"
       "  --navdata DIR          BlueSky navdata folder (airports.dat, fix.dat, nav.dat)\n",
       cmd_run},
      {"test", "test [DIR|FILE...]       run Lua regression scripts (default tests/lua/)",
       "usage: squawk test [DIR|FILE...] [--seed N] [--max-instructions N] [--navdata DIR]\n\n"
       "Runs every *.lua file in the given folders (default tests/lua/), each in a\n"
       "fresh sandboxed VM. Scripts use the assertion API:\n"
       "  check(cond, [msg])            passes when cond is truthy\n"
       "  check_eq(got, want, [msg])    passes when got == want\n"
       "  check_near(got, want, tol, [msg])  passes when |got - want| <= tol\n"
       "A failed check prints file:line and the values; the script goes on. A script\n"
       "passes when it ends without error and with no failed check. The last line\n"
       "is `N passed, N failed`; the exit code is 1 when any script failed.\n",
       cmd_test},
      {"render", "render EPISODE.jsonl      draw a recorded episode as SVG (Fig. 2 style)",
       "usage: squawk render EPISODE.jsonl [--frame N] [--size PX] [--out FILE.svg|-]\n\n"
       "Draws a recorded episode top-down, north up: the ownship's and intruders'\n"
       "tracks, each intruder's separation circle (red while the ownship is inside),\n"
       "the waypoint with its capture circle, a scale bar and a north arrow.\n"
       "Episodes are recorded by `squawk demo --record FILE` and `squawk eval --record FILE`.\n"
       "  --frame N   draw aircraft where they were at recorded frame N (default: last)\n"
       "  --out FILE  output path (default: the input with .svg; `-` = stdout)\n"
       "For a PNG: rsvg-convert -o out.png out.svg (Debian package librsvg2-bin).\n",
       cmd_render},
      {"plot", "plot RUN_DIR|FILE.csv      draw training curves as SVG (Fig. 3 style)",
       "usage: squawk plot RUN_DIR|FILE.csv [--out FILE.svg|-]\n\n"
       "Reads the CSV logs a training run writes (columns episodes, success_rate,\n"
       "mean_reward) and draws success rate and mean reward against episodes\n"
       "trained, one line per CSV file. Default output: RUN_DIR/curves.svg.\n",
       cmd_plot},
      {"rag", "rag search QUERY | rag eval CORPUS.tsv   command retrieval (BM25)",
       "usage: squawk rag search QUERY... [--k N] [--text] [--notes FILE] [--no-notes]\n"
       "       squawk rag eval CORPUS.tsv [--k N] [--misses] [--notes FILE] [--no-notes]\n\n"
       "Ranks the TrafScript commands for an English request with BM25 over the\n"
       "command registry's documentation plus the retrieval notes in\n"
       "scripts/translate/phraseology.txt (NAME: words per line).\n"
       "`search` prints the best N commands with their scores (--text adds the\n"
       "documents). `eval` reads a translator corpus (id, setup, utterance,\n"
       "expected, category) and prints Recall@1 and Recall@N: the share of cases\n"
       "whose expected commands are all among the first N retrieved. ASK cases\n"
       "are counted apart; --misses lists the cases retrieval got wrong.\n\n"
       "  --k N          how many documents to retrieve (default 5)\n"
       "  --notes FILE   retrieval notes to use instead of the shipped ones\n"
       "  --no-notes     the registry documentation alone\n",
       cmd_rag},
  };
  return table;
}

}  // namespace squawk::app
