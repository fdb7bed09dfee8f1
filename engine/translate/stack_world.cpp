#include "translate/stack_world.h"

#include "core/text.h"

namespace squawk::translate {

Status setup_stack(command::Stack& stack, std::string_view setup) {
  if (text::trim(setup).empty()) return Status::ok();
  // Queued like a scenario line: commands squawk lacks (display-only ones
  // such as TRAIL) are skipped, real failures are kept in the tally.
  stack.schedule(stack.sim().simt(), std::string(setup));
  stack.process_due();
  const auto& tally = stack.tally();
  if (!tally.failed.empty()) {
    std::string msg = "setup failed: ";
    msg.append(tally.first_failures.empty() ? tally.failed.begin()->first : tally.first_failures.front());
    return Status::invalid(msg);
  }
  return Status::ok();
}

}  // namespace squawk::translate
