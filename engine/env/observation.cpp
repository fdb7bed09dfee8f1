#include "env/observation.h"

namespace squawk::env {

namespace {
// Copies n values at a time in the flattened (alphabetical) order.
template <class Fn>
void visit_flat(int n, Fn&& fn) {
  fn(0, n);          // cos_difference_pos
  fn(n, 1);          // cos_drift
  fn(n + 1, n);      // intruder_distance
  fn(2 * n + 1, n);  // sin_difference_pos
  fn(3 * n + 1, 1);  // sin_drift
  fn(3 * n + 2, 1);  // waypoint_distance
  fn(3 * n + 3, n);  // x_difference_speed
  fn(4 * n + 3, n);  // y_difference_speed
}
}  // namespace

void flatten(const Observation& o, std::span<float> out) {
  const int n = o.num_intruders();
  const double* src[8] = {o.cos_difference_pos.data(), &o.cos_drift,
                          o.intruder_distance.data(),  o.sin_difference_pos.data(),
                          &o.sin_drift,                &o.waypoint_distance,
                          o.x_difference_speed.data(), o.y_difference_speed.data()};
  int field = 0;
  visit_flat(n, [&](int at, int count) {
    for (int k = 0; k < count; ++k) out[static_cast<size_t>(at + k)] = static_cast<float>(src[field][k]);
    ++field;
  });
}

Result<Observation> unflatten(std::span<const float> flat) {
  const int size = static_cast<int>(flat.size());
  if (size < 8 || (size - 3) % 5 != 0)
    return Status::invalid("observation of " + std::to_string(size) +
                           " values: expected 3 + 5 * intruders (28 for 5 intruders)");
  const int n = (size - 3) / 5;
  Observation o;
  for (auto* v : {&o.intruder_distance, &o.cos_difference_pos, &o.sin_difference_pos,
                  &o.x_difference_speed, &o.y_difference_speed})
    v->resize(static_cast<size_t>(n));
  double* dst[8] = {o.cos_difference_pos.data(), &o.cos_drift,
                    o.intruder_distance.data(),  o.sin_difference_pos.data(),
                    &o.sin_drift,                &o.waypoint_distance,
                    o.x_difference_speed.data(), o.y_difference_speed.data()};
  int field = 0;
  visit_flat(n, [&](int at, int count) {
    for (int k = 0; k < count; ++k) dst[field][k] = flat[static_cast<size_t>(at + k)];
    ++field;
  });
  return o;
}

ObservationMirror observation_mirror(int num_intruders, double own_speed_ratio) {
  Observation scale, offset;
  for (auto* o : {&scale, &offset}) {
    for (auto* v : {&o->intruder_distance, &o->cos_difference_pos, &o->sin_difference_pos,
                    &o->x_difference_speed, &o->y_difference_speed})
      v->assign(static_cast<size_t>(num_intruders), 0.0);
    o->waypoint_distance = o->cos_drift = o->sin_drift = 0.0;
  }
  for (int i = 0; i < num_intruders; ++i) {
    const auto k = static_cast<size_t>(i);
    scale.intruder_distance[k] = scale.cos_difference_pos[k] = scale.x_difference_speed[k] = 1.0;
    scale.sin_difference_pos[k] = scale.y_difference_speed[k] = -1.0;
    offset.y_difference_speed[k] = 2.0 * own_speed_ratio;
  }
  scale.waypoint_distance = scale.cos_drift = 1.0;
  scale.sin_drift = -1.0;
  const auto size = static_cast<size_t>(observation_size(num_intruders));
  ObservationMirror m{std::vector<float>(size), std::vector<float>(size)};
  flatten(scale, m.scale);
  flatten(offset, m.offset);
  return m;
}

const std::vector<std::string>& observation_field_names() {
  static const std::vector<std::string> names = {
      "intruder_distance",  "cos_difference_pos", "sin_difference_pos", "x_difference_speed",
      "y_difference_speed", "waypoint_distance",  "cos_drift",          "sin_drift"};
  return names;
}

}  // namespace squawk::env
