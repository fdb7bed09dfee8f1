#include "rl/slot_permutation.h"

#include <algorithm>
#include <charconv>
#include <utility>

namespace squawk::rl {

namespace {

bool parse_int(std::string_view s, int& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && !s.empty();
}

}  // namespace

Result<SlotLayout> parse_slot_layout(const std::string& spec, int obs_size) {
  const auto fail = [&](const std::string& why) {
    return Status::invalid("slot layout '" + spec + "': " + why);
  };
  const size_t colon = spec.find(':');
  SlotLayout layout;
  if (colon == std::string::npos ||
      !parse_int(std::string_view(spec).substr(0, colon), layout.count))
    return fail("expected COUNT:START[,START...] (integers)");
  if (layout.count < 2) return fail("expected at least 2 slots");
  std::string_view rest = std::string_view(spec).substr(colon + 1);
  while (true) {
    const size_t comma = rest.find(',');
    int start = 0;
    if (!parse_int(rest.substr(0, comma), start))
      return fail("expected COUNT:START[,START...] (integers)");
    if (start < 0 || start + layout.count > obs_size)
      return fail("block " + std::to_string(start) + ".." +
                  std::to_string(start + layout.count - 1) + " lies outside the observation's " +
                  std::to_string(obs_size) + " numbers");
    layout.starts.push_back(start);
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  std::vector<int> sorted = layout.starts;
  std::ranges::sort(sorted);
  for (size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i] < sorted[i - 1] + layout.count)
      return fail("blocks at " + std::to_string(sorted[i - 1]) + " and " +
                  std::to_string(sorted[i]) + " overlap (each holds " +
                  std::to_string(layout.count) + " numbers)");
  return layout;
}

void permute_slots(std::span<float> obs, const SlotLayout& layout, Rng& rng) {
  for (int i = layout.count - 1; i > 0; --i) {
    const auto j = static_cast<int>(rng.uniform_int(0, i));
    if (j == i) continue;
    for (const int s : layout.starts)
      std::swap(obs[static_cast<size_t>(s + i)], obs[static_cast<size_t>(s + j)]);
  }
}

}  // namespace squawk::rl
