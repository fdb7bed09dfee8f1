// The flags every script-running subcommand shares, and their VmOptions.
#pragma once

#include "app/cli.h"
#include "script/vm.h"

namespace squawk::app {

// Adds --seed --unsafe --out --max-instructions --max-seconds --navdata
// --allow-read to `spec`.
// --allow-read DIR[:DIR...] names folders scripts may read besides their own.
Args::Spec with_vm_flags(Args::Spec spec);
// VmOptions from the parsed flags (navdata also from $SQUAWK_NAVDATA).
Result<script::VmOptions> vm_options(const Args& args);
// The optional SCENARIO positional of repl/serve: its absolute path ("" when
// none or an empty one was given), kNotFound when the file is absent. The file's folder
// becomes readable in `o` (the user named it, so its siblings may be IC'd).
Result<std::string> named_scenario(const Args& args, script::VmOptions& o);

}  // namespace squawk::app
