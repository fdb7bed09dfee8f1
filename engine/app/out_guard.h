// What a command may replace when it writes: a training run's folder
// (--out DIR) and the single files of render, plot and table3 --csv.
#pragma once

#include <string>
#include <vector>

#include "app/cli.h"
#include "app/subcommands.h"
#include "core/status.h"

namespace squawk::app {

// Decides what `squawk train ARGV` does with its --out folder before either
// learner parses ARGV (`spec`: the union of both learners' flags):
// - DIR holds no run (none of checkpoint.ckpt, log.csv, best.ckpt,
//   policy.ckpt): ARGV unchanged;
// - DIR holds a run and neither --resume nor --force is given: error naming
//   DIR, the files found and both flags;
// - --force: the run's files are removed; ARGV unchanged;
// - --resume with DIR/run.json: ARGV becomes the scenario and flags the run
//   started with plus the flags that do not shape a run (--quiet, --stop-at,
//   the VM's limits and paths) given now. Error naming the flag when one given
//   now contradicts the record or shapes the run but was not given at its start;
// - --resume --override: ARGV unchanged (the flags given now replace the
//   record: a recipe's next stage); --override without --resume is an error.
// The error message is what the user sees after "squawk train: ".
Result<ArgV> resolve_train_argv(const ArgV& argv, const Args::Spec& spec);

// Writes DIR/run.json for a run that starts now: its scenario (absolute) and
// every flag of `args` that shapes the run. Error: the file cannot be written.
Status record_run(const std::string& dir, const Args& args);

// A file command may write `path` (render, plot, table3 --csv): it may when
// `path` is absent, when --force was given, or when the file begins with
// `own_prefix` (what this command writes: squawk replaces its own output).
// Error otherwise, naming the file and --force; and when `path` is a folder.
Status check_overwrite(const std::string& path, const std::string& own_prefix, bool force);

// A command that writes `target` (a file, or a folder whose `files` it
// writes) may when none of them exists or --force was given. Error naming
// `target`, the files found and --force otherwise.
Status check_absent(const std::string& target, const std::vector<std::string>& files, bool force);

}  // namespace squawk::app
