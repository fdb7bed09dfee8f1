// Entry points of the subcommands, one per app/cli_<area>.cpp function.
// Each takes the arguments after the subcommand name and returns an exit code.
#pragma once

#include <string>
#include <vector>

namespace squawk::app {

using ArgV = std::vector<std::string>;

int cmd_run(const ArgV& args);   // cli_script.cpp
int cmd_test(const ArgV& args);  // cli_script.cpp
int cmd_render(const ArgV& args);  // cli_viz.cpp
int cmd_plot(const ArgV& args);    // cli_viz.cpp
int cmd_rag(const ArgV& args);     // cli_rag.cpp

}  // namespace squawk::app
