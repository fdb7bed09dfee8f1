// Traffic for a translation case.
//
// Contract: setup_stack() runs a corpus setup (TrafScript commands separated
// by ';') on a fresh Stack and returns the error of the first command that
// fails, naming it; commands squawk does not have are skipped, as in a
// scenario file.
#pragma once

#include <string_view>

#include "command/stack.h"
#include "core/status.h"

namespace squawk::translate {

Status setup_stack(command::Stack& stack, std::string_view setup);

}  // namespace squawk::translate
