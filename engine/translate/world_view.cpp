#include "translate/world_view.h"

#include "core/text.h"

namespace squawk::translate {

std::optional<AircraftView> WorldView::find(std::string_view id) const {
  for (auto& a : aircraft())
    if (text::iequals(a.id, id)) return a;
  return std::nullopt;
}

}  // namespace squawk::translate
