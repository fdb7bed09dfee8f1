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

}  // namespace squawk::app
