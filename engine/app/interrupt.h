// Ctrl-C for long commands (train): while an InterruptGuard lives, the first
// SIGINT only sets a flag that the command polls, so it can save its
// checkpoint and exit cleanly; the guard restores SIGINT's default action at
// that first signal, so a second Ctrl-C ends the process at once. The
// previous handler is restored when the guard goes.
#pragma once

#include <csignal>

namespace squawk::app {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // True once SIGINT arrived while a guard was alive.
  static bool requested();

 private:
  struct sigaction previous_ {};
};

// Exit status of a command ended by SIGINT (128 + 2, the shell's convention).
inline constexpr int kExitInterrupted = 130;

}  // namespace squawk::app
