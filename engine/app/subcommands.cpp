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
  };
  return table;
}

}  // namespace squawk::app
