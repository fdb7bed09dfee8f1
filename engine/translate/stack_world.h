// WorldView over a live command::Stack: the aircraft and user waypoints of
// its Simulation, read at each call (no copy kept).
//
// Contract: the Stack must outlive the view. setup_stack() runs a corpus
// setup (TrafScript commands separated by ';') on a fresh Stack and returns
// the error of the first command that fails, naming it; commands squawk
// does not have are skipped, as in a scenario file.
#pragma once

#include <string_view>

#include "command/stack.h"
#include "core/status.h"
#include "translate/world_view.h"

namespace squawk::translate {

class StackWorld : public WorldView {
 public:
  explicit StackWorld(const command::Stack& stack) : stack_(stack) {}
  std::vector<AircraftView> aircraft() const override;
  std::vector<std::string> waypoints() const override;

 private:
  const command::Stack& stack_;
};

Status setup_stack(command::Stack& stack, std::string_view setup);

}  // namespace squawk::translate
