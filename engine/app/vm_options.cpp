#include "app/vm_options.h"

#include <cstdlib>
#include <filesystem>

#include "core/files.h"
#include "core/paths.h"
#include "core/text.h"

namespace squawk::app {

Args::Spec with_vm_flags(Args::Spec spec) {
  for (const char* f : {"--seed", "--out", "--max-instructions", "--max-seconds", "--max-memory",
                        "--max-conflict-pairs", "--navdata", "--allow-read"})
    spec.value_flags.emplace_back(f);
  spec.bool_flags.emplace_back("--unsafe");
  return spec;
}

Result<script::VmOptions> vm_options(const Args& args) {
  script::VmOptions o;
  auto seed = args.get_int("--seed", 0);
  if (!seed) return seed.status();
  if (*seed < 0) return Status::invalid("flag --seed expects a non-negative integer");
  o.seed = static_cast<uint64_t>(*seed);
  auto maxi = args.get_int("--max-instructions", o.max_instructions);
  if (!maxi) return maxi.status();
  if (*maxi < 0)
    return Status::invalid("flag --max-instructions expects a count >= 0 (0 = no limit), got " +
                           std::to_string(*maxi));
  o.max_instructions = *maxi;
  auto maxs = args.get_double("--max-seconds", 0.0);
  if (!maxs) return maxs.status();
  if (!(*maxs >= 0) || *maxs > 1e9)
    return Status::invalid("flag --max-seconds expects seconds >= 0 (0 = no limit)");
  o.max_seconds = *maxs;
  auto maxm = args.get_int("--max-memory", o.max_memory >> 20);
  if (!maxm) return maxm.status();
  if (*maxm < 0 || *maxm > (1LL << 30))
    return Status::invalid("flag --max-memory expects MiB in [0, 2^30] (0 = no limit), got " + std::to_string(*maxm));
  o.max_memory = *maxm << 20;
  auto cap = args.get_int("--max-conflict-pairs", o.max_conflict_pairs);
  if (!cap) return cap.status();
  if (*cap < 1)
    return Status::invalid("flag --max-conflict-pairs expects a count >= 1, got " + std::to_string(*cap));
  o.max_conflict_pairs = *cap;
  o.unsafe = args.has("--unsafe");
  if (auto out = args.get("--out")) {
    SQUAWK_RETURN_IF_ERROR(files::make_dirs(*out));
    o.out_dir = paths::absolute(*out);
  }
  if (auto dirs = args.get("--allow-read")) {
    for (const auto& d : text::split(*dirs, ':')) {
      if (d.empty()) continue;
      if (!std::filesystem::is_directory(d)) return Status::not_found("--allow-read " + d + ": no such folder");
      o.read_dirs.push_back(paths::absolute(d));
    }
  }
  if (auto nav = args.get("--navdata")) {
    o.navdata_dir = *nav;
  } else if (const char* env = std::getenv("SQUAWK_NAVDATA"); env && *env) {
    o.navdata_dir = env;
  }
  return o;
}

Status check_scn_file(const std::string& path, bool scn) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec))
    return Status::invalid(path + " is a folder; expected one FILE.scn" +
                           (scn ? " (`squawk scn " + path + " --conformance` runs every .scn under it)" : ""));
  if (text::lower(fs::path(path).extension().string()) == ".lua")
    return Status::invalid(path + " is a Lua conflict-resolution scenario: `squawk train`, `squawk eval` and "
                           "`squawk table3` take it; this command runs BlueSky .scn files (e.g. "
                           "scenarios/demo_conflict.scn)");
  if (!fs::exists(path, ec)) return Status::not_found("no scenario file '" + path + "'");
  return Status::ok();
}

Result<std::string> named_scenario(const Args& args, script::VmOptions& o) {
  if (args.positional().empty() || args.positional()[0].empty()) return std::string();
  SQUAWK_RETURN_IF_ERROR(check_scn_file(args.positional()[0], false));
  const std::string path = paths::absolute(args.positional()[0]);
  o.read_dirs.push_back(std::filesystem::path(path).parent_path().string());
  return path;
}

int load_episode_scenario(const Args& args, const std::string& subcommand, script::VmOptions& vm,
                          script::Scenario& sc) {
  auto vo = vm_options(args);
  if (!vo) return usage_error(subcommand, vo.status().message());
  vm = std::move(*vo);
  vm.out_dir.clear();
  auto loaded = script::load_scenario(args.positional()[0], vm);
  if (!loaded) return failure(loaded.status());
  sc = std::move(*loaded);
  return kExitOk;
}

}  // namespace squawk::app
