// squawk executable: all logic lives in the engine (app/cli.h).
#include <cstdio>

#include "app/cli.h"
#include "app/interrupt.h"
#include "core/heap.h"
#include "dist/comm.h"

int main(int argc, char** argv) {
  squawk::heap::keep_freed_memory();
  squawk::dist::init(&argc, &argv);
  // In a data-parallel job rank 0 alone prints results; every rank keeps stderr for its errors.
  if (squawk::dist::rank() > 0 && !std::freopen("/dev/null", "w", stdout)) return 1;
  const int rc = squawk::app::run_cli(argc, argv);
  // A rank that fails alone would leave the others waiting in their next
  // collective: it ends the job. An interrupt is agreed by every rank.
  if (rc != 0 && rc != squawk::app::kExitInterrupted && squawk::dist::size() > 1) squawk::dist::abort(rc);
  squawk::dist::finalize();
  return rc;
}
