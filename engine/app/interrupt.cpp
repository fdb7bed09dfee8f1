#include "app/interrupt.h"

#include "dist/comm.h"

namespace squawk::app {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_interrupt(int sig) {
  g_interrupted = 1;
  std::signal(sig, SIG_DFL);
}

}  // namespace

InterruptGuard::InterruptGuard() : term_(dist::size() > 1) {
  g_interrupted = 0;
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &previous_);
  if (term_) sigaction(SIGTERM, &sa, &previous_term_);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previous_, nullptr);
  if (term_) sigaction(SIGTERM, &previous_term_, nullptr);
}

bool InterruptGuard::requested() { return g_interrupted != 0; }

}  // namespace squawk::app
