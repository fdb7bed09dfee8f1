// What a translation of one request gives: commands to run, or a question.
//
// Contract: exactly one of three outcomes: `commands` (TrafScript lines in
// execution order, several for several instructions), `ask` (a question
// back naming what is missing, or a yes/no question before destructive or
// global commands, which then stand in `on_yes`; no command is issued), or
// `error` (the translator produced nothing it could validate; no command is
// issued).
#pragma once

#include <string>
#include <vector>

namespace squawk::translate {

struct Translation {
  std::vector<std::string> commands;  // TrafScript lines, in execution order
  std::string ask;                    // a question back; empty when commands were produced
  std::vector<std::string> on_yes;    // with a yes/no `ask`: the commands a yes runs
  std::string error;                  // why no valid command came out; empty otherwise
  std::string note;  // what was said that squawk does not simulate; empty otherwise
  bool asked() const { return !ask.empty(); }
  bool issued() const { return ask.empty() && error.empty() && !commands.empty(); }
  // "CMD ; CMD", or the question when one was asked, or "error: ..." .
  std::string text() const;
};

}  // namespace squawk::translate
