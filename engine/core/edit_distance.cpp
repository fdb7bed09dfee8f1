#include "core/edit_distance.h"

#include <algorithm>
#include <vector>

namespace squawk::text {

size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows: two back (for swaps), one back, current.
  std::vector<size_t> back2(b.size() + 1), back1(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) back1[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      cur[j] = std::min({back1[j] + 1, cur[j - 1] + 1, back1[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) cur[j] = std::min(cur[j], back2[j - 2] + 1);
    }
    std::swap(back2, back1);
    std::swap(back1, cur);
  }
  return back1[b.size()];
}

}  // namespace squawk::text
