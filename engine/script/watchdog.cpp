#include "script/watchdog.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace squawk::script {

Watchdog::Watchdog(double seconds, double grace, std::string stuck_message)
    : stuck_message_(std::move(stuck_message)), thread_([this, seconds, grace] { watch(seconds, grace); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mu_);
    disarmed_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void Watchdog::watch(double seconds, double grace) {
  using clock = std::chrono::steady_clock;
  std::unique_lock<std::mutex> lock(mu_);
  const auto deadline = clock::now() + std::chrono::duration<double>(seconds);
  if (cv_.wait_until(lock, deadline, [this] { return disarmed_; })) return;
  expired_.store(true, std::memory_order_relaxed);
  const auto last = clock::now() + std::chrono::duration<double>(grace);
  if (cv_.wait_until(lock, last, [this] { return disarmed_; })) return;
  std::fprintf(stderr, "%s\n", stuck_message_.c_str());
  std::fflush(stderr);
  std::_Exit(124);
}

}  // namespace squawk::script
