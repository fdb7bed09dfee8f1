// A command that must fail, checked the registry's way.
//
// Contract: error_of(s, line) requires that executing `line` fails, checks
// that the stack's snapshot is byte-for-byte what it was before (a failed
// command leaves nothing half-applied), and returns the error's message.
#pragma once

#include <doctest/doctest.h>

#include <string>

#include "command/stack.h"

namespace squawk::test {

inline std::string error_of(command::Stack& s, const std::string& line) {
  const std::string before = s.snapshot();
  auto r = s.exec(line);
  REQUIRE_MESSAGE(!r, line);
  CHECK_MESSAGE(s.snapshot() == before, line);
  return r.status().message();
}

}  // namespace squawk::test
