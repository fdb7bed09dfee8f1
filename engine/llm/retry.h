// RetryPolicy: bounded retries with exponential backoff.
//
// Contract: an attempt is retried only when it failed in transport
// (kUnavailable: refused, reset, DNS; kTimeout) or the server answered with
// a 5xx status, and only while no streamed output has reached the caller.
// Attempt k (k >= 1) waits initial_backoff_s * multiplier^(k-1), capped at
// max_backoff_s, before attempt k+1. The wait goes through `sleep` so tests
// run without real delays.
#pragma once

#include <functional>

#include "core/status.h"

namespace squawk::llm {

struct RetryPolicy {
  int max_attempts = 3;            // total attempts, >= 1
  double initial_backoff_s = 0.5;  // [s] wait after the first failure
  double multiplier = 2.0;         // growth of the wait per failure
  double max_backoff_s = 8.0;      // [s] cap of one wait
  std::function<void(double seconds)> sleep;  // empty: real sleep

  // Wait before attempt `next_attempt` (2, 3, ...). [s]
  double backoff_before(int next_attempt) const;
  void wait_before(int next_attempt) const;
};

// True for the failures worth retrying: transport errors and HTTP 5xx.
bool is_retryable(const Status& transport_status, long http_status);

}  // namespace squawk::llm
