// squawk executable: all logic lives in the engine (app/cli.h).
#include "app/cli.h"

int main(int argc, char** argv) { return squawk::app::run_cli(argc, argv); }
