// Entry points of the subcommands, one per app/cli_<area>.cpp function.
// Each takes the arguments after the subcommand name and returns an exit code.
#pragma once

#include <string>
#include <vector>

namespace squawk::app {

using ArgV = std::vector<std::string>;

int cmd_run(const ArgV& args);   // cli_script.cpp
int cmd_test(const ArgV& args);  // cli_script.cpp
int cmd_train(const ArgV& args);  // cli_rl.cpp
int cmd_eval(const ArgV& args);   // cli_rl.cpp
int cmd_table3(const ArgV& args);  // cli_table3.cpp
int cmd_gpt2(const ArgV& args);  // cli_gpt2.cpp
int cmd_demo(const ArgV& args);    // cli_demo.cpp
int cmd_render(const ArgV& args);  // cli_viz.cpp
int cmd_plot(const ArgV& args);    // cli_viz.cpp
int cmd_rag(const ArgV& args);     // cli_rag.cpp
int cmd_repl(const ArgV& args);    // cli_repl.cpp
int cmd_serve(const ArgV& args);   // cli_serve.cpp
int cmd_llm(const ArgV& args);     // cli_llm.cpp
int cmd_scn(const ArgV& args);       // cli_sim.cpp
int cmd_commands(const ArgV& args);  // cli_sim.cpp
int cmd_env(const ArgV& args);       // cli_env.cpp
int cmd_translate(const ArgV& args);       // cli_translate.cpp
int cmd_eval_translate(const ArgV& args);  // cli_translate.cpp

}  // namespace squawk::app
