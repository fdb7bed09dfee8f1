// squawk run / squawk test.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "core/files.h"

namespace fs = std::filesystem;

namespace squawk::app {

int cmd_run(const ArgV& argv) {
  Args::Spec spec = with_vm_flags({});
  spec.pass_unknown = true;
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("run", args.status().message());
  if (args->positional().empty()) return usage_error("run", "missing FILE.lua");
  auto opts = vm_options(*args);
  if (!opts) return usage_error("run", opts.status().message());
  const std::string file = args->positional()[0];
  if (!files::exists(file)) return failure(Status::not_found("no script '" + file + "'"));
  std::vector<std::string> script_args(args->positional().begin() + 1, args->positional().end());
  script::Vm vm(*opts);
  Status st = vm.run_file(file, script_args);
  if (!st.is_ok()) {
    std::fprintf(stderr, "%s\n", shown_error(st.message()).c_str());
    return kExitFail;
  }
  return vm.checks().failed > 0 ? kExitFail : kExitOk;
}

int cmd_test(const ArgV& argv) {
  auto args = Args::parse(argv, with_vm_flags({}));
  if (!args) return usage_error("test", args.status().message());
  auto opts = vm_options(*args);
  if (!opts) return usage_error("test", opts.status().message());
  std::vector<std::string> targets = args->positional();
  if (targets.empty()) targets.push_back("tests/lua");

  std::vector<std::string> scripts;
  for (const auto& t : targets) {
    std::error_code ec;
    if (fs::is_directory(t, ec)) {
      std::vector<std::string> found;
      for (const auto& e : fs::recursive_directory_iterator(t, ec))
        if (e.is_regular_file() && e.path().extension() == ".lua") found.push_back(e.path().string());
      std::sort(found.begin(), found.end());
      if (found.empty()) return usage_error("test", "no *.lua scripts in '" + t + "'");
      scripts.insert(scripts.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(t, ec)) {
      scripts.push_back(t);
    } else {
      return usage_error("test", "no folder or file '" + t + "'");
    }
  }

  int passed = 0, failed = 0;
  for (const auto& path : scripts) {
    script::Vm vm(*opts);
    Status st = vm.run_file(path);
    const auto& c = vm.checks();
    const bool ok = st.is_ok() && c.failed == 0;
    if (!st.is_ok()) std::printf("%s\n", shown_error(st.message()).c_str());
    std::printf("%s %s (%ld checks passed, %ld failed)\n", ok ? "ok  " : "FAIL", path.c_str(),
                c.passed, c.failed);
    std::fflush(stdout);
    (ok ? passed : failed)++;
  }
  std::printf("%d passed, %d failed\n", passed, failed);
  return failed ? kExitFail : kExitOk;
}

}  // namespace squawk::app
