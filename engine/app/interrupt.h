// Ctrl-C for long commands (train): while an InterruptGuard lives, the first
// SIGINT only sets a flag that the command polls, so it can save its
// checkpoint and exit cleanly; the guard restores SIGINT's default action at
// that first signal, so a second Ctrl-C ends the process at once. The
// previous handler is restored when the guard goes.
// In a data-parallel job (dist/comm.h) SIGTERM counts as SIGINT: mpirun and
// srun pass a Ctrl-C on to every rank as SIGTERM, and the ranks agree to stop
// at the same batch (rl::Trainer::update).
#pragma once

#include <csignal>

namespace squawk::app {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // True once SIGINT (or, in a job of several ranks, SIGTERM) arrived while a guard was alive.
  static bool requested();

 private:
  bool term_ = false;  // SIGTERM handled too
  struct sigaction previous_ {};
  struct sigaction previous_term_ {};
};

// Exit status of a command ended by SIGINT (128 + 2, the shell's convention).
inline constexpr int kExitInterrupted = 130;

}  // namespace squawk::app
