#include "app/out_guard.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/files.h"
#include "core/text.h"
#include "dist/comm.h"

namespace fs = std::filesystem;

namespace squawk::app {

namespace {

// The files a training run writes into its folder: any of the first four
// means the folder holds a run (run.json alone is a start that failed before
// training, which a new run replaces).
constexpr const char* kRunFiles[] = {"checkpoint.ckpt", "log.csv", "best.ckpt", "policy.ckpt", "run.json"};
constexpr size_t kRunMarkers = 4;

// Flags that choose where a run writes, how it talks or how far this session
// goes, not what the run computes: they may differ between a run and its --resume.
bool shapes_run(const std::string& flag) {
  static const std::vector<std::string> free = {"--out",       "--resume",     "--force",     "--override",
                                                "--quiet",     "--stop-at",    "--max-seconds",
                                                "--max-instructions", "--allow-read", "--navdata",
                                                "--unsafe"};
  return std::find(free.begin(), free.end(), flag) == free.end();
}

std::string canonical(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? path : p.string();
}

void append_flag(ArgV& out, const std::string& name, const std::string& value, const Args::Spec& spec) {
  out.push_back(name);
  if (std::find(spec.bool_flags.begin(), spec.bool_flags.end(), name) == spec.bool_flags.end()) out.push_back(value);
}

std::string shown(const std::string& name, const std::string& value, const Args::Spec& spec) {
  const bool is_bool = std::find(spec.bool_flags.begin(), spec.bool_flags.end(), name) != spec.bool_flags.end();
  return is_bool ? name : name + " " + value;
}

}  // namespace

Result<ArgV> resolve_train_argv(const ArgV& argv, const Args::Spec& spec) {
  auto args = Args::parse(argv, spec);
  if (!args || !args->has("--out")) return argv;  // the learner reports what is wrong
  const std::string dir = *args->get("--out");
  const bool resume = args->has("--resume"), force = args->has("--force");
  if (resume && force) return Status::invalid("--resume and --force contradict each other: choose one");
  if (args->has("--override") && !resume)
    return Status::invalid("--override goes with --resume (it replaces the flags of a run that continues)");
  // Rank 0 alone looks and removes, and tells the others: a rank that starts later would see (or
  // delete) the files rank 0 has begun to write.
  std::vector<std::string> found;
  std::string removal_error;
  if (dist::rank() == 0) {
    for (size_t k = 0; k < kRunMarkers; ++k)
      if (files::exists(dir + "/" + kRunFiles[k])) found.emplace_back(kRunFiles[k]);
    for (const char* f : kRunFiles) {
      if (found.empty() || !force || !removal_error.empty()) break;
      std::error_code ec;
      fs::remove(dir + "/" + f, ec);
      if (ec) removal_error = "--force: cannot remove " + dir + "/" + f + ": " + ec.message();
    }
  }
  std::byte seen[2] = {std::byte{static_cast<unsigned char>(!found.empty())},
                       std::byte{static_cast<unsigned char>(!removal_error.empty())}};
  dist::broadcast({seen, 2}, 0);
  if (!static_cast<bool>(seen[0])) return argv;
  if (force) {
    if (static_cast<bool>(seen[1]))
      return Status::io_error(removal_error.empty()
                                  ? "--force: rank 0 cannot remove the run in " + dir
                                  : removal_error);
    return argv;
  }
  if (found.empty()) found.emplace_back("as rank 0 sees it");
  if (!resume)
    return Status::invalid("--out " + dir + " already holds a run (" + text::join(found, ", ") +
                           "): --resume continues it, --force deletes it and starts over, or choose another --out");
  const std::string record_path = dir + "/run.json";
  if (args->has("--override")) return argv;  // the flags given now replace run.json (open_run_folder)
  if (!files::exists(record_path)) {
    std::fprintf(stderr, "squawk train: note: %s has no run.json (a run from an older squawk): the flags given now "
                 "set the rest of the run\n", dir.c_str());
    return argv;
  }
  SQUAWK_ASSIGN_OR_RETURN(std::string text, files::read(record_path));
  nlohmann::json rec = nlohmann::json::parse(text, nullptr, false);
  if (rec.is_discarded() || !rec.is_object() || !rec.contains("scenario") || !rec["scenario"].is_string() ||
      !rec.contains("flags") || !rec["flags"].is_object())
    return Status::invalid(record_path + ": expected {\"scenario\": PATH, \"flags\": {...}}; --force starts over");
  const std::string scenario = rec["scenario"].get<std::string>();
  std::map<std::string, std::string> recorded;
  for (const auto& [name, value] : rec["flags"].items()) {
    if (!value.is_string()) return Status::invalid(record_path + ": flag " + name + " is not a string");
    recorded[name] = value.get<std::string>();
  }
  const std::string hint = "; --resume continues the run with the settings in " + record_path +
                           " (drop the flag; or add --override to continue the checkpoint with the flags given now, "
                           "a recipe's next stage; or train into another --out)";
  if (args->positional().size() > 1) return argv;  // the learner reports it
  if (args->positional().size() == 1 && canonical(args->positional()[0]) != canonical(scenario))
    return Status::invalid("--resume: scenario " + args->positional()[0] + " is not the run's " + scenario + hint);
  ArgV merged = {scenario};
  for (const auto& [name, value] : args->flags()) {
    if (!shapes_run(name)) {
      append_flag(merged, name, value, spec);
      continue;
    }
    auto it = recorded.find(name);
    if (it == recorded.end())
      return Status::invalid("--resume: " + shown(name, value, spec) + " was not given when the run started" + hint);
    if (it->second != value)
      return Status::invalid("--resume: " + shown(name, value, spec) + " contradicts the run's " +
                             shown(name, it->second, spec) + hint);
  }
  for (const auto& [name, value] : recorded) append_flag(merged, name, value, spec);
  return merged;
}

Status record_run(const std::string& dir, const Args& args) {
  nlohmann::json flags = nlohmann::json::object();
  for (const auto& [name, value] : args.flags())
    if (shapes_run(name)) flags[name] = value;
  const std::string scenario = args.positional().empty() ? "" : canonical(args.positional()[0]);
  nlohmann::json rec = {{"scenario", scenario}, {"flags", flags}};
  return files::write_atomic(dir + "/run.json", rec.dump(1) + "\n");
}

Status check_overwrite(const std::string& path, const std::string& own_prefix, bool force) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return Status::invalid(path + " is a folder; expected a file name");
  if (force || !fs::exists(path, ec)) return Status::ok();
  auto text = files::read(path);
  if (text && text->compare(0, own_prefix.size(), own_prefix) == 0) return Status::ok();
  return Status::invalid(path + " exists and is not a file this command wrote; --force replaces it");
}

Status check_absent(const std::string& target, const std::vector<std::string>& names, bool force) {
  if (force) return Status::ok();
  std::vector<std::string> found;
  for (const auto& f : names)
    if (files::exists(f)) found.push_back(fs::path(f).filename().string());
  if (found.empty()) return Status::ok();
  const std::string what = names.size() == 1 && names[0] == target ? " exists" : " already holds " + text::join(found, ", ");
  return Status::invalid(target + what + ": --force replaces it, or choose another name");
}

}  // namespace squawk::app
