#include "translate/translation.h"

#include "core/text.h"

namespace squawk::translate {

std::string Translation::text() const {
  if (asked()) return ask;
  if (!error.empty()) return "error: " + error;
  return text::join(commands, " ; ");
}

}  // namespace squawk::translate
