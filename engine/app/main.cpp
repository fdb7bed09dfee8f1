// squawk executable: all logic lives in the engine (app/cli.h).
#include "app/cli.h"
#include "core/heap.h"

int main(int argc, char** argv) {
  squawk::heap::keep_freed_memory();
  return squawk::app::run_cli(argc, argv);
}
