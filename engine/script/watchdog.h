// Watchdog: a wall-clock deadline for one call into a Vm.
//
// Contract: `seconds` after construction the watchdog sets expired() (the
// Vm's count hook turns that into a Lua error at the script's next
// instructions). A call stuck inside one C function cannot be interrupted:
// when the watchdog is still armed `grace` seconds after that, it prints
// `stuck_message` to stderr and ends the process with exit code 124. The
// destructor disarms it and joins its thread.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace squawk::script {

class Watchdog {
 public:
  Watchdog(double seconds, double grace, std::string stuck_message);
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

  bool expired() const { return expired_.load(std::memory_order_relaxed); }

 private:
  void watch(double seconds, double grace);

  std::string stuck_message_;
  std::atomic<bool> expired_{false};
  std::mutex mu_;
  std::condition_variable cv_;
  bool disarmed_ = false;
  std::thread thread_;
};

}  // namespace squawk::script
