// Simulation control and scripting commands: OP, HOLD, FF, DT, DTMULT, RESET,
// IC, PCALL, SEED, ECHO, HELP, SCHEDULE, DELAY, NOISE, TRAIL, NEAR.
#include "command/handler_util.h"
#include "command/line.h"
#include "core/text.h"

namespace squawk::command {

namespace {

Result<std::string> op(Call& c) {
  c.stack.sim().op();
  return std::string();
}

Result<std::string> hold(Call& c) {
  c.stack.sim().hold();
  return std::string();
}

Result<std::string> ff(Call& c) {
  std::optional<double> d;
  if (c.has(0)) d = c[0].num;
  SQUAWK_RETURN_IF_ERROR(c.stack.sim().fast_forward(d));
  return std::string();
}

Result<std::string> dt(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0))
    return "dt " + text::fmt_double(s.dt(), 4) + " s, asas " + text::fmt_double(s.cd_settings().asas_dt, 4) + " s";
  if (c[0].type == ArgType::kFloat) {
    if (c.has(1)) return Status::invalid("argument 2: DT with one number sets the step; a timer name comes first");
    SQUAWK_RETURN_IF_ERROR(s.set_dt(c[0].num));
    return std::string();
  }
  if (c[0].text != "ASAS")
    return Status::invalid("argument 1: expected a step in seconds or the timer name ASAS, got " +
                           text::quoted(c[0].text));
  if (!c.has(1)) return Status::invalid("argument 2: missing the ASAS interval in seconds");
  SQUAWK_RETURN_IF_ERROR(s.set_asas_dt(c[1].num));
  return std::string();
}

Result<std::string> dtmult(Call& c) {
  if (!(c[0].num > 0.0)) return Status::invalid("argument 1: the multiplier must be > 0");
  c.stack.set_dtmult(c[0].num);
  return std::string();
}

Result<std::string> reset(Call& c) {
  c.stack.reset();
  return std::string();
}

Result<std::string> ic(Call& c) {
  const std::string name(text::trim(c[0].text));
  if (name.empty()) return Status::invalid("argument 1: missing the scenario file name");
  SQUAWK_RETURN_IF_ERROR(c.stack.load_scenario(name));
  return std::string();
}

// PCALL file [REL/ABS] [args...]; "PCALL acid file ..." means "PCALL file acid ...".
Result<std::string> pcall(Call& c) {
  std::vector<std::string> words = tokenize(c[0].text);
  if (words.empty() || words[0].empty()) return Status::invalid("argument 1: missing the scenario file name");
  if (words.size() > 1 && c.stack.sim().index_of(words[0]) >= 0) std::swap(words[0], words[1]);
  std::string file = words[0];
  std::vector<std::string> args(words.begin() + 1, words.end());
  bool relative = true;
  if (!args.empty() && (text::iequals(args[0], "REL") || text::iequals(args[0], "ABS"))) {
    relative = text::iequals(args[0], "REL");
    args.erase(args.begin());
  }
  SQUAWK_RETURN_IF_ERROR(c.stack.merge_scenario(file, args, relative));
  return std::string();
}

Result<std::string> seed(Call& c) {
  if (c[0].num < 0) return Status::invalid("argument 1: the seed must be >= 0");
  c.stack.set_seed(static_cast<uint64_t>(c[0].num));
  return std::string();
}

Result<std::string> echo(Call& c) { return c.has(0) ? c[0].text : std::string(); }

Result<std::string> help(Call& c) { return Registry::instance().help(c.has(0) ? c[0].text : ""); }

Result<std::string> schedule(Call& c) {
  if (text::trim(c[1].text).empty()) return Status::invalid("argument 2: missing the command to schedule");
  c.stack.schedule(c[0].num, std::string(text::trim(c[1].text)));
  return std::string();
}

Result<std::string> delay(Call& c) {
  if (text::trim(c[1].text).empty()) return Status::invalid("argument 2: missing the command to delay");
  if (c[0].num < 0) return Status::invalid("argument 1: the delay must be >= 0 s");
  c.stack.schedule(c.stack.sim().simt() + c[0].num, std::string(text::trim(c[1].text)));
  return std::string();
}

Result<std::string> noise(Call& c) {
  if (!c.has(0)) return std::string("NOISE ") + on_off(c.stack.noise());
  c.stack.set_noise(c[0].on);
  return c[0].on ? std::string("NOISE ON recorded; squawk models no turbulence or ADS-B noise") : std::string();
}

// TRAIL ON/OFF [dt] or TRAIL acid BLUE/RED/YELLOW; bare TRAIL shows the setting.
Result<std::string> trail(Call& c) {
  Trails& t = c.stack.trails();
  if (!c.has(0)) return std::string("TRAIL ") + on_off(t.on) + ", a point every " + text::fmt_double(t.dt, 4) + " s";
  if (c[0].type == ArgType::kOnOff) {
    if (c.has(1) && c[1].type != ArgType::kFloat)
      return Status::invalid("argument 2: TRAIL ON/OFF takes the time between trail points in seconds, got " +
                             text::quoted(c[1].text));
    if (c.has(1) && !(c[1].num > 0.0)) return Status::invalid("argument 2: the trail time step must be > 0 s");
    t.on = c[0].on;
    if (c.has(1)) t.dt = c[1].num;
    return std::string();
  }
  const std::string colour = c.has(1) ? c[1].text : std::string();
  if (colour != "BLUE" && colour != "RED" && colour != "YELLOW")
    return Status::invalid("argument 2: the trail colour of an aircraft is BLUE, RED or YELLOW, got " +
                           (colour.empty() ? std::string("nothing") : text::quoted(colour)));
  const sim::Traffic& traffic = c.stack.sim().traffic();
  for (int i : c[0].acids) t.colour[traffic.id[static_cast<size_t>(i)]] = colour;
  return std::string();
}

// NEAR position,command: the reference position (args.h) moves to the position
// (an aircraft's too), then the command runs from it.
Result<std::string> near(Call& c) {
  if (text::trim(c[1].text).empty())
    return Status::invalid("argument 2: missing the command to run");
  c.stack.set_reference(c[0].pos);
  return c.stack.run_nested(c[1].text);
}

}  // namespace

void add_sim_commands(std::vector<CommandDecl>& out) {
  out.push_back(
      {"OP",
       {"CONTINUE", "RUN", "START"},
       "",
       "OP",
       "Sets the simulation running in real time: ends fast-time and sets DTMULT to 1, as "
       "BlueSky. Headless runs advance regardless.",
       {"OP"},
       op,
       {}});
  out.push_back({"HOLD", {"PAUSE"}, "", "HOLD",
                 "Pauses the simulation clock of an interactive session. Headless runs advance regardless.",
                 {"HOLD"}, hold, {}});
  out.push_back(
      {"FF",
       {"FWD"},
       "[time]",
       "FF [seconds]",
       "Runs in fast-time, for the given time (SS, MM:SS or HH:MM:SS) or until HOLD or OP; "
       "when the time is up it runs on in real time (OP: DTMULT 1), as BlueSky.",
       {"FF", "FF 0:05:00"},
       ff,
       {}});
  out.push_back({"DT", {}, "[float/txt,float]", "DT [dt] or DT ASAS,dt",
                 "Sets the simulation time step in seconds (default 0.05), or the interval of conflict "
                 "detection with DT ASAS; without arguments shows both.",
                 {"DT 0.1", "DT ASAS 2"}, dt, {}});
  out.push_back({"DTMULT", {"RTF"}, "float", "DTMULT multiplier",
                 "Sets how many times faster than real time an interactive session runs (recorded; headless "
                 "runs are not paced).",
                 {"DTMULT 5"}, dtmult, {}});
  out.push_back({"RESET", {}, "", "RESET",
                 "Clears everything: aircraft, routes, conflicts, settings, queued and conditional commands, "
                 "user waypoints; the clock goes back to 0.",
                 {"RESET"}, reset, {}});
  out.push_back({"IC", {"LOAD", "OPEN"}, "string", "IC filename",
                 "Resets the simulation and loads a scenario file (.scn), whose timed commands then run as the "
                 "clock passes their times. Relative names are looked up in the scenario's folder.",
                 {"IC demo_conflict.scn"}, ic, {}});
  out.push_back({"PCALL", {"CALL"}, "string", "PCALL filename,[REL/ABS],[args...]",
                 "Merges another scenario file into the running one. Its times count from now (REL, default) or "
                 "from 0 (ABS); %0, %1, ... in its lines are replaced by the extra arguments.",
                 {"PCALL approach.scn", "PCALL sid.scn REL KL204"}, pcall, {}});
  out.push_back({"SEED", {}, "int", "SEED value",
                 "Seeds the simulation's random generator (used by MCRE), so runs repeat exactly.", {"SEED 42"},
                 seed, {}});
  out.push_back({"ECHO", {}, "[string]", "ECHO text", "Prints the text to the console or scenario log.",
                 {"ECHO Conflict ahead"}, echo, {}});
  out.push_back({"HELP", {"?"}, "[txt]", "HELP [command]",
                 "Lists the commands, or explains one: usage, aliases, what it does, examples.", {"HELP ALT"},
                 help, {}});
  out.push_back({"SCHEDULE", {}, "time,string", "SCHEDULE time,command",
                 "Queues a command to run when the simulation clock reaches the given time (HH:MM:SS or "
                 "seconds).",
                 {"SCHEDULE 00:30:00 HOLD", "SCHEDULE 120 KL204 ALT FL100"}, schedule, {}});
  out.push_back({"DELAY", {}, "time,string", "DELAY time,command",
                 "Queues a command to run after the given time from now.", {"DELAY 60 KL204 HDG 090"}, delay, {}});
  out.push_back({"NOISE", {}, "[onoff]", "NOISE [ON/OFF]",
                 "Records the turbulence and ADS-B noise switch; squawk models neither, so ON says so and has "
                 "no effect on the dynamics.",
                 {"NOISE OFF"}, noise, {}});
  out.push_back({"TRAIL", {"TRAILS"}, "[acid/onoff],[float/txt]", "TRAIL ON/OFF,[dt] or TRAIL acid,colour",
                 "Switches the radar display's aircraft trails on or off, optionally with the time between "
                 "trail points in seconds (default 10), or sets one aircraft's trail colour (BLUE, RED or "
                 "YELLOW). A display setting: it does not change the traffic.",
                 {"TRAIL ON", "TRAIL ON 5", "TRAIL KL204 RED"}, trail, {}});
  out.push_back(
      {"NEAR",
       {},
       "latlon,string",
       "NEAR lat,lon,command",
       "Runs a command with the reference position moved to lat lon first, so a navaid or fix name "
       "in it is the one of that name nearest there. The reference otherwise follows the aircraft "
       "and positions of the commands before; RESET and IC put it back at 0 0. squawk also takes a "
       "named place or an aircraft as the position (BlueSky takes lat lon only).",
       {"NEAR 51.6 0.2 CRE KL204 A320 LAM 90 FL100 250"},
       near,
       {}});
}

}  // namespace squawk::command
