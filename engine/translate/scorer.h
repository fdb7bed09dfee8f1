// Scoring of translations against a corpus's expected TrafScript, following
// the rules of shared/corpora/README.md.
//
// Contract: a produced command list is correct when it equals the expected
// list, or one of its ` || ` alternatives, command by command in order after
// normalisation: command aliases folded to the command registry's names
// (CREATE->CRE, HEADING/TURN->HDG, SPEED->SPD, DCT->DIRECT, PAUSE->HOLD,
// ASAS->CDMETHOD, DELETE->DEL, ...); names case-insensitive; altitudes in feet within 50 ft
// (FL300 = 30000); speeds in knots within 0.5 kt or Mach within 0.0005
// (M0.78 = .78); vertical speeds within 1 ft/min; latitude/longitude within
// 1e-3 deg; headings modulo 360 within 0.5 deg; other numbers equal numerically; ATALT/ATSPD
// compare their condition and then the nested command the same way. "AT acid wp alt/spd" is
// "AT acid wp ALT alt ; AT acid wp SPD spd" (either order). With the case's setup given,
// "ADDWPT acid X,,,END" where END is the waypoint acid's route ends with after the setup is
// "ADDWPT acid X" (ADDWPT appends there: the same route). Expected `ASK` is correct only
// when the translator asked. Pure functions.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace squawk::translate {

// Splits "A ; B" into trimmed commands; empty parts are dropped.
std::vector<std::string> split_commands(std::string_view list);
// Command name with aliases folded, upper case ("turn" -> "HDG").
std::string canonical_command(std::string_view name);
// True when two single commands are equal under the rules above.
bool same_command(std::string_view produced, std::string_view expected);
// Scores one case. `asked` is true when the translator asked a question
// (then `produced` is ignored); `setup` is the case's TrafScript run before it.
bool score_case(std::string_view produced, bool asked, std::string_view expected,
                std::string_view setup = {});

}  // namespace squawk::translate
