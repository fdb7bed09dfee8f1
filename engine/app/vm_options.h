// The flags every script-running subcommand shares, and their VmOptions.
#pragma once

#include "app/cli.h"
#include "script/scenario.h"
#include "script/vm.h"

namespace squawk::app {

// Adds --seed --unsafe --out --max-instructions --max-seconds --max-memory
// --navdata --allow-read to `spec`. --max-memory MB caps each VM's Lua heap.
// --allow-read DIR[:DIR...] names folders scripts may read besides their own.
Args::Spec with_vm_flags(Args::Spec spec);
// VmOptions from the parsed flags (navdata also from $SQUAWK_NAVDATA).
Result<script::VmOptions> vm_options(const Args& args);
// The optional SCENARIO positional of repl/serve: its absolute path ("" when
// none or an empty one was given), kNotFound when the file is absent. The file's folder
// becomes readable in `o` (the user named it, so its siblings may be IC'd).
Result<std::string> named_scenario(const Args& args, script::VmOptions& o);
// Error unless `path` names a BlueSky scenario file (what scn, repl and serve
// load): for a folder it says so (and, with `scn`, that --conformance runs
// every .scn under one); for a .lua file, that it is a conflict-resolution
// scenario and that train, eval and table3 take it.
Status check_scn_file(const std::string& path, bool scn);
// The scenario file positional()[0] of a subcommand that runs episodes: `vm`
// from the flags with no writable folder (loading a scenario writes nothing),
// then the strict loader into `sc`. Returns 0, or the exit code after printing
// the error: usage (2) for bad flags, failure (1) for the file.
int load_episode_scenario(const Args& args, const std::string& subcommand, script::VmOptions& vm,
                          script::Scenario& sc);

}  // namespace squawk::app
