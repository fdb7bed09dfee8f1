// Retrieval's name for the one edit distance of squawk (core/edit_distance.h).
#pragma once

#include "core/edit_distance.h"

namespace squawk::rag {

using text::edit_distance;

}  // namespace squawk::rag
