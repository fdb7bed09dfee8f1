#include "llm/retry.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace squawk::llm {

double RetryPolicy::backoff_before(int next_attempt) const {
  const int failures = std::max(1, next_attempt - 1);
  const double w = initial_backoff_s * std::pow(multiplier, failures - 1);
  return std::clamp(w, 0.0, max_backoff_s);
}

void RetryPolicy::wait_before(int next_attempt) const {
  const double s = backoff_before(next_attempt);
  if (sleep) {
    sleep(s);
  } else if (s > 0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(s));
  }
}

bool is_retryable(const Status& transport_status, long http_status) {
  if (!transport_status.is_ok())
    return transport_status.code() == Code::kUnavailable || transport_status.code() == Code::kTimeout;
  return http_status >= 500 && http_status <= 599;
}

}  // namespace squawk::llm
