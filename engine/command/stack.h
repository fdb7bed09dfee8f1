// Stack: a Simulation plus the command layer around it: the TrafScript
// console that the CLI, .scn runner, Lua and the translator drive.
//
// State it owns beside the Simulation (all part of snapshot()):
//  - the queue of timed commands (scenario lines, SCHEDULE, DELAY, PCALL),
//    ordered by (time, arrival);
//  - conditional commands (ATALT / ATSPD / ATDIST); the commands of route
//    waypoints (AT acid wp DO) live in the route (sim::Waypoint::commands) and
//    run, like a met condition's, at the step after the waypoint is passed;
//  - user waypoints (DEFWPT);
//  - the reference position (BlueSky's bs.ref, args.h): where the last
//    successful command's parse left it; a navaid or fix named in a position
//    is the one of that name nearest it. (0, 0) after construction, RESET and
//    IC; a failed command leaves it as it was;
//  - the seed RESET uses, and switches squawk records without modelling
//    (DTMULT, NOISE), and the display's trail settings (TRAIL).
// Counters (tally) and collected output are bookkeeping, not state.
//
// Line rules (BlueSky, docs/bluesky_facts.md §2.1): `;` splits commands; names are
// case-insensitive; an aircraft id may come before the command
// ("KL204 ALT FL100"); a bare aircraft id means POS.
//
// Errors: a failed command returns a Status whose message starts with the
// command as typed, names the argument and the expected form, and ends with
// the usage; the stack and the simulation are exactly as before.
//
// Time: run_until() processes, at each step, the queued commands whose time is
// <= simt, then steps the simulation, then tests the conditions (a condition
// whose threshold was crossed runs its command at the next step, as BlueSky).
// Headless runs ignore the run state (HOLD/OP/FF only set it).
//
// Copying a Stack copies everything (navdata is shared, read-only): the
// translator validates commands on a scratch copy.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "command/args.h"
#include "command/navdb.h"
#include "command/scn.h"
#include "core/path_rules.h"
#include "core/status.h"
#include "sim/simulation.h"

namespace squawk::command {

// What happened to the commands a stack ran (for summaries and conformance).
struct Tally {
  long executed = 0;                      // commands that succeeded
  std::map<std::string, long> skipped;    // scenario commands squawk lacks, by name
  std::map<std::string, long> failed;     // failures by command and reason (values blanked)
  std::vector<std::string> first_failures;  // the first kMaxKept failure messages, with time
  static constexpr size_t kMaxKept = 50;
};

// TRAIL (BlueSky traffic/trails.py): trails on/off, the time between trail
// points, and colours chosen per aircraft (by callsign; BLUE, RED or YELLOW).
struct Trails {
  bool on = false;
  double dt = 10.0;  // [s]
  std::map<std::string, std::string> colour;
};

struct Condition {
  enum class Kind { kAlt = 0, kSpd = 1, kDist = 2 };
  std::string acid;
  Kind kind = Kind::kAlt;
  double target = 0.0;     // [m] alt, [m/s] CAS, or [NM] distance
  double last_diff = 0.0;  // target - actual at the previous test
  GeoPoint pos;            // kDist: the reference position
  std::string command;     // run when target - actual changes sign
  std::string where;       // "file:line" of the scenario line that set it ("" when typed)
};

// A command line waiting in the queue, with the scenario line it came from.
struct Queued {
  std::string line;
  std::string where;  // "file:line" ("" for a typed command); a failure reads "t=T s: file:line: message"
};

class Stack {
 public:
  explicit Stack(uint64_t seed = 0);

  sim::Simulation& sim() { return sim_; }
  const sim::Simulation& sim() const { return sim_; }

  void set_navdb(std::shared_ptr<const NavDb> db) { navdb_ = std::move(db); }
  const NavDb* navdb() const { return navdb_.get(); }
  // Folder where IC / PCALL file names are looked up when relative (see
  // find_scenario).
  void set_base_dir(std::string dir) { base_dir_ = std::move(dir); }
  const std::string& base_dir() const { return base_dir_; }
  // IC / PCALL files and PERF OPENAP folders are read only when `rules`
  // allows it (a sandbox's read check; `rules` must outlive the stack);
  // nullptr (the default): every file.
  void set_path_rules(const paths::PathRules* rules) { rules_ = rules; }
  // The read check of set_path_rules for a file, and for a folder whose
  // files a loader reads (paths::PathRules::check_read_folder).
  Status check_read(const std::string& path, std::string_view what) const;
  Status check_read_folder(const std::string& dir, std::string_view what) const;

  // Runs a line now (one or more `;` commands, as typed by a user). Stops at
  // the first failing command (earlier ones keep their effect) and returns its
  // error; otherwise the joined output of the commands.
  Result<std::string> exec(std::string_view line);
  // Parse-only validation of a line: command names and argument forms are
  // checked against the current state; nothing runs. Checks that need the
  // handler (duplicate callsign, LNAV without route) are not made here.
  Status check(std::string_view line) const;

  // IC: resets everything, then queues `path`'s commands at their times.
  Status load_scenario(const std::string& path);
  // PCALL: merges a scenario file. Times are relative to now unless
  // `relative` is false; %0, %1, ... are replaced by `args`.
  Status merge_scenario(const std::string& path, const std::vector<std::string>& args, bool relative);
  // Queues a command line to run when simt >= t [s], reported (on failure) at
  // the scenario line running now (SCHEDULE, DELAY from a file) or at none. A
  // full queue (10^6 commands) drops it and records a failure. At most 10^5
  // queued commands run at one sim time; the rest due then are dropped with a failure.
  void schedule(double t, std::string line);

  // Runs (queued commands, steps, conditions) up to t_end [s]; see above.
  // Queued commands that fail are counted and logged, not returned. With a
  // deadline set, the clock is read every 64 queued commands and every step:
  // past it, run_until returns kTimeout and the rest stay queued.
  Status run_until(double t_end);
  void set_deadline(std::optional<std::chrono::steady_clock::time_point> d) { deadline_ = d; }
  // One step: due commands, Simulation::step, conditions.
  void step();
  // Runs the commands due at the current time without stepping.
  void process_due();

  // Time of the last queued command [s], if any.
  std::optional<double> last_queued_time() const;
  size_t queued() const { return queue_.size(); }
  const std::vector<Condition>& conditions() const { return conditions_; }
  const std::map<std::string, GeoPoint>& user_waypoints() const { return user_wpts_; }
  // The reference position the next command's parse starts from [deg].
  GeoPoint reference() const { return ref_; }

  // Deterministic bytes of the full state: Simulation::snapshot() followed by
  // the command-layer state listed at the top.
  std::string snapshot() const;

  const Tally& tally() const { return tally_; }
  // Output of queued commands (ECHO text, failures) since the last call.
  std::vector<std::string> take_output();

  // --- For handlers (commands_*.cpp) ----------------------------------------
  ParseContext parse_context() const;
  void add_condition(Condition c) {
    c.where = where_;
    conditions_.push_back(std::move(c));
  }
  Status define_waypoint(const std::string& name, GeoPoint pos);
  Status delete_user_waypoint(const std::string& name);
  // NEAR: sets the reference position before a handler runs its command.
  void set_reference(GeoPoint p) { ref_ = p; }
  // Runs one command (no `;`) from a handler (NEAR), as a line of the
  // scenario running now or as typed when none runs; the caller's own
  // failure handling covers it. Error: more than 8 nested in one another.
  Result<std::string> run_nested(std::string_view command);
  // RESET: simulation, queue, conditions, user waypoints, reference (seed kept).
  void reset();
  uint64_t seed() const { return seed_; }
  void set_seed(uint64_t seed);
  double dtmult() const { return sim_.dtmult(); }
  void set_dtmult(double m) { sim_.set_dtmult(m); }
  bool noise() const { return noise_; }
  void set_noise(bool on) { noise_ = on; }
  // TRAIL: the radar display's aircraft trails (state only; squawk's
  // dynamics do not read it).
  const Trails& trails() const { return trails_; }
  Trails& trails() { return trails_; }
  // Resolves a scenario file name: absolute as given; relative in base_dir,
  // then in each parent folder of base_dir; the .scn suffix is added and
  // matched in any case. Error names the file and where it looked.
  Result<std::string> find_scenario(const std::string& name) const;

 private:
  // Runs one command (no `;`). from_queue: it came from a scenario/schedule,
  // so BlueSky commands squawk does not implement (command/bluesky_only.h:
  // display, GUI, plugins) are skipped and *skipped is set; any other unknown
  // name is an error that names the closest registry command.
  Result<std::string> run_command(std::string_view text, bool from_queue, bool* skipped);
  // Runs a queued line; failures are counted and reported at q.where.
  void run_queued(const Queued& q);
  // The scenario file `path` resolves to and its entries, checked against the
  // nesting cap and the read filter.
  Result<std::pair<std::string, ScnFile>> read_included(const std::string& path) const;
  // Queues a parsed file's entries (with %n replaced); those already due run
  // at once, in file order, before anything else queued (as BlueSky merges).
  void merge_entries(const std::string& file, ScnFile scn, const std::vector<std::string>& args,
                     bool relative);
  void test_conditions();
  // Queues, for the next step, the commands of the route waypoints passed in
  // the last sim step (sim::Simulation::passages), reported at "ACID AT WPT".
  void queue_passages();

  sim::Simulation sim_;
  std::shared_ptr<const NavDb> navdb_;
  std::string base_dir_ = ".";
  std::map<std::pair<double, uint64_t>, Queued> queue_;  // (time [s], arrival) -> line
  uint64_t next_seq_ = 0;
  std::vector<Condition> conditions_;
  std::vector<Queued> fired_;  // condition commands due at the next step
  std::string where_;          // "file:line" of the queued line running now ("" when none)
  std::map<std::string, GeoPoint> user_wpts_;
  GeoPoint ref_;  // the reference position [deg]
  uint64_t seed_ = 0;
  bool noise_ = false;
  Trails trails_;
  // Counts and logs a failure that belongs to no single command.
  void record_failure(const std::string& what);

  const paths::PathRules* rules_ = nullptr;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  bool past_deadline() const { return deadline_ && std::chrono::steady_clock::now() > *deadline_; }
  int include_depth_ = 0;  // PCALL nesting guard (not state: always 0 between calls)
  int nested_depth_ = 0;   // run_nested guard (not state: always 0 between calls)

  Tally tally_;
  std::vector<std::string> output_;
};

}  // namespace squawk::command
