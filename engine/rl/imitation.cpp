#include "rl/imitation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "nn/adam.h"
#include "rl/play.h"

namespace squawk::rl {

namespace {

struct Labelled {
  std::vector<float> obs;           // [N, obs_size]
  std::vector<ActionSample> label;  // [N] the teacher's greedy actions
};

// Flies `count` episodes from `first` of `seed` with `pilot` (greedy or
// sampled), appending every decision with the teacher's greedy action and,
// when `flights` is given, every ended episode's observations and rewards;
// returns the flights' success rate (over every episode flown, those that
// ended before a decision included).
Result<double> fly(env::BatchEnv& envs, Policy& pilot, bool greedy, Policy& teacher, uint64_t seed,
                   uint64_t first, uint64_t count, Rng& rng, Labelled& out,
                   TeacherFlights* flights) {
  std::vector<ActionSample> taught;
  const auto d = static_cast<size_t>(envs.obs_size());
  std::vector<TeacherFlights> running(flights ? static_cast<size_t>(envs.size()) : 0);  // per slot
  Driver driver;
  driver.choose = [&](Turn& t) {
    const int n = static_cast<int>(t.slots.size());
    taught.assign(static_cast<size_t>(n), {});
    teacher.act(t.obs, n, t.slots, {&rng, 1}, true, taught);
    if (&pilot == &teacher) {
      std::copy(taught.begin(), taught.end(), t.actions.begin());
    } else {
      pilot.act(t.obs, n, t.slots, {&rng, 1}, greedy, t.actions);
    }
    SQUAWK_RETURN_IF_ERROR(teacher.error());
    SQUAWK_RETURN_IF_ERROR(pilot.error());
    out.obs.insert(out.obs.end(), t.obs.begin(), t.obs.end());
    out.label.insert(out.label.end(), taught.begin(), taught.end());
    if (flights)
      for (size_t r = 0; r < t.slots.size(); ++r) {
        auto& o = running[static_cast<size_t>(t.slots[r])].obs;
        o.insert(o.end(), t.obs.begin() + static_cast<long>(r * d),
                 t.obs.begin() + static_cast<long>((r + 1) * d));
      }
    return Status::ok();
  };
  if (flights)
    driver.after = [&](const Turn& t) {
      for (size_t r = 0; r < t.slots.size(); ++r) {
        TeacherFlights& e = running[static_cast<size_t>(t.slots[r])];
        e.rewards.push_back(t.rewards[r]);
        if (!t.dones[r]) continue;
        flights->obs.insert(flights->obs.end(), e.obs.begin(), e.obs.end());
        flights->rewards.insert(flights->rewards.end(), e.rewards.begin(), e.rewards.end());
        flights->lengths.push_back(static_cast<int>(e.rewards.size()));
        e = TeacherFlights{};
      }
      return true;
    };
  SQUAWK_RETURN_IF_ERROR(play(envs, seed, first, count, driver).status());
  const auto& done = envs.completed();
  const auto ok = std::count_if(done.begin(), done.end(), [](const env::EpisodeStats& e) { return e.success; });
  return done.empty() ? 0.0 : static_cast<double>(ok) / static_cast<double>(done.size());
}

Status check_pair(Policy& student, Policy& teacher) {
  if (!student.trainable()) return Status::invalid("imitation: the student " + student.name() + " is not trainable");
  const auto s = student.action_values(), t = teacher.action_values();
  if (s.empty() != t.empty())
    return Status::invalid("imitation: the teacher " + teacher.name() + " has " +
                           (t.empty() ? "a continuous action" : "discrete classes") +
                           ", the student " + student.name() +
                           (s.empty() ? " has a continuous one" : " has discrete classes") +
                           " (expected the same kind)");
  if (!std::equal(s.begin(), s.end(), t.begin(), t.end()))
    return Status::invalid("imitation: the teacher " + teacher.name() + " and the student " + student.name() +
                           " have different action classes");
  return check_obs_size(student, teacher.obs_size());
}

}  // namespace

Result<TeacherFlights> greedy_flights(Policy& pilot, env::BatchEnv& envs, uint64_t seed,
                                      uint64_t count) {
  SQUAWK_RETURN_IF_ERROR(check_obs_size(pilot, envs.obs_size()));
  Rng rng(seed);
  Labelled decisions;
  TeacherFlights flights;
  SQUAWK_RETURN_IF_ERROR(
      fly(envs, pilot, true, pilot, seed, 0, count, rng, decisions, &flights).status());
  return flights;
}

Status imitate(Policy& student, Policy& teacher, env::BatchEnv& envs, const ImitationConfig& c,
               const std::function<Status(const ImitationEpoch&)>& on_epoch,
               TeacherFlights* flights) {
  SQUAWK_RETURN_IF_ERROR(check_pair(student, teacher));
  if (c.episodes < 1 || c.rounds < 1 || c.epochs < 1 || c.batch < 1 || c.holdout < 1 || !(c.lr > 0.0f))
    return Status::invalid("imitation: episodes, rounds, epochs, batch and holdout must be >= 1 and lr > 0");
  if (c.holdout_seed == c.seed) return Status::invalid("imitation: the held-out seed must differ from the training seed");
  if (c.held_tail > student.params().size())
    return Status::invalid("imitation: held_tail " + std::to_string(c.held_tail) +
                           " exceeds the student's " + std::to_string(student.params().size()) +
                           " parameters");
  const bool continuous = student.action_values().empty();
  if (!(c.saturated_label >= 1.0f) || (c.saturated_label != 1.0f && !continuous))
    return Status::invalid("imitation: saturated_label " + std::to_string(c.saturated_label) +
                           " (expected >= 1, and 1 for a discrete head)");
  const auto d = static_cast<size_t>(teacher.obs_size());
  for (const int s : c.permute.starts)
    if (c.permute.count >= 2 && (s < 0 || static_cast<size_t>(s + c.permute.count) > d))
      return Status::invalid("imitation: the permuted block at " + std::to_string(s) + " (" +
                             std::to_string(c.permute.count) + " slots) lies outside the " +
                             std::to_string(d) + " observation numbers");
  Rng rng(c.seed);
  Labelled held, data;
  SQUAWK_RETURN_IF_ERROR(fly(envs, teacher, true, teacher, c.holdout_seed, 0,
                             static_cast<uint64_t>(c.holdout), rng, held, nullptr)
                             .status());
  const int n_held = static_cast<int>(held.label.size());
  nn::Adam adam(student.params(), student.grads(), {.lr = c.lr, .grad_clip = c.grad_clip});
  std::vector<float> batch_obs(static_cast<size_t>(c.batch) * d), coef(static_cast<size_t>(c.batch),
                                                                       1.0f / static_cast<float>(c.batch));
  std::vector<ActionSample> batch_act(static_cast<size_t>(c.batch)), held_act(static_cast<size_t>(n_held));
  const std::vector<int> no_slots(static_cast<size_t>(std::max(n_held, c.batch)), 0);
  for (int round = 0; round < c.rounds; ++round) {
    const bool teacher_flies = round == 0;
    SQUAWK_ASSIGN_OR_RETURN(
        double success,
        fly(envs, teacher_flies ? teacher : student, false, teacher, c.seed,
            static_cast<uint64_t>(round) * static_cast<uint64_t>(c.episodes),
            static_cast<uint64_t>(c.episodes), rng, data, teacher_flies ? flights : nullptr));
    const int n = static_cast<int>(data.label.size());
    std::vector<int> order(static_cast<size_t>(n));
    for (int epoch = 0; epoch < c.epochs; ++epoch) {
      std::iota(order.begin(), order.end(), 0);
      for (int i = n - 1; i > 0; --i) std::swap(order[static_cast<size_t>(i)], order[static_cast<size_t>(rng.uniform_int(0, i))]);
      for (int b0 = 0; b0 + c.batch <= n; b0 += c.batch) {
        for (int r = 0; r < c.batch; ++r) {
          const auto row = static_cast<size_t>(order[static_cast<size_t>(b0 + r)]);
          std::copy_n(data.obs.begin() + static_cast<long>(row * d), d, batch_obs.begin() + static_cast<long>(r * d));
          ActionSample& y = batch_act[static_cast<size_t>(r)];
          y = data.label[row];
          if (continuous)  // unused components are 0
            for (int j = 0; j < kMaxActionSize; ++j)
              if (std::abs(y.component(j)) >= 1.0f)
                y.component(j) = std::copysign(c.saturated_label, y.component(j));
        }
        if (c.permute.count >= 2)
          for (size_t r = 0; r < static_cast<size_t>(c.batch); ++r)
            permute_slots(std::span<float>(batch_obs.data() + r * d, d), c.permute, rng);
        std::fill(student.grads().begin(), student.grads().end(), 0.0f);
        student.accumulate_gradient(batch_obs, c.batch, batch_act, coef, 0.0f);
        std::ranges::fill(student.grads().last(c.held_tail), 0.0f);  // Adam moves them by 0
        adam.step();
        SQUAWK_RETURN_IF_ERROR(student.error());
      }
      student.act(held.obs, n_held, std::span<const int>(no_slots).first(static_cast<size_t>(n_held)), {&rng, 1}, true,
                  held_act);
      SQUAWK_RETURN_IF_ERROR(student.error());
      int agree = 0;
      double error = 0.0;
      for (int r = 0; r < n_held; ++r) {
        const ActionSample &a = held_act[static_cast<size_t>(r)],
                           &y = held.label[static_cast<size_t>(r)];
        double diff = 0.0;  // the largest component's (unused components are 0 in both)
        for (int j = 0; j < kMaxActionSize; ++j) {
          const float flown = continuous ? std::clamp(a.component(j), -1.0f, 1.0f) : a.component(j);
          diff = std::max(
              diff, std::abs(static_cast<double>(flown) - static_cast<double>(y.component(j))));
        }
        agree += continuous ? diff <= kContinuousAgreement : a.index == y.index;
        error += diff;
      }
      const double held_n = std::max(1, n_held);
      SQUAWK_RETURN_IF_ERROR(
          on_epoch({round, epoch, teacher_flies, success, n, agree / held_n, error / held_n}));
    }
  }
  return Status::ok();
}

}  // namespace squawk::rl
