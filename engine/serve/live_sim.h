// LiveSim: the simulation of `squawk serve`, running live on one owner thread.
//
// The owner thread is the only one that touches the simulation, the Lua VM and
// the teammate. It advances the clock as the run state asks (the session's
// tick: HOLD none, OP real time x DTMULT, FF to its end at once),
// runs the requests other threads post, and publishes the state (JSON text,
// state_json.h plus `log`, `advisories`, `auto`, `teammate`) at publish_hz
// and after every request. Other threads only post requests (call) and read
// the last published state (state / wait_state), so a slow HTTP client can
// never stall the simulation.
//
// The log records who did what: "controller" for typed commands and
// decisions, "teammate" for advisories, "auto" for advisories executed in the
// automatic mode, "scenario" for scenario output (ECHO, failed queued lines),
// "autopilot" for the teammate's own steering, "sim" for conflicts and losses
// of separation as they start and end. Of more than log_shown entries the
// oldest "sim", "autopilot" or "scenario" one is dropped first, so that the
// decisions (controller, teammate, auto) stay in view longest.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <future>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/status.h"
#include "script/serve_session.h"

namespace squawk::serve {

// The AI side of the team, called on the owner thread after each advance.
class Teammate {
 public:
  struct Output {
    std::vector<std::string> advisories;  // English lines for the controller to accept or reject
    std::vector<std::string> notes;       // log lines (the teammate's own automatic commands)
  };
  virtual ~Teammate() = default;
  virtual Result<Output> tick(command::Stack& stack) = 0;
};

struct LiveOptions {
  double publish_hz = 10.0;            // [1/s] state pushes (>= 5 for the page)
  double max_owed_s = 60.0;            // [s] sim time the clock may fall behind before it skips
  size_t max_queue = 64;               // [-] pending requests before new ones are refused
  size_t log_shown = 60;               // [-] log entries in the published state
  size_t advisories_shown = 12;        // [-] advisories in the published state
  bool auto_advisories = false;        // execute advisories without asking
};

class LiveSim {
 public:
  LiveSim(script::ServeSession& session, LiveOptions options, Teammate* teammate = nullptr);
  ~LiveSim();
  LiveSim(const LiveSim&) = delete;
  LiveSim& operator=(const LiveSim&) = delete;

  void start();
  void stop();

  // --- Any thread -----------------------------------------------------------
  using Request = std::function<nlohmann::json(LiveSim&)>;
  // Runs `fn` on the owner thread and returns its JSON. Errors: the queue is
  // full or the server is stopping (unavailable), no answer within `timeout`
  // (deadline exceeded; the request still runs).
  Result<nlohmann::json> call(Request fn, std::chrono::milliseconds timeout);
  // The last published state and its version (1, 2, ...).
  std::pair<uint64_t, std::shared_ptr<const std::string>> state() const;
  // Waits up to `timeout` for a version newer than `after`; returns the newest.
  std::pair<uint64_t, std::shared_ptr<const std::string>> wait_state(uint64_t after,
                                                                     std::chrono::milliseconds timeout) const;
  bool stopping() const;

  // --- Owner thread only (inside a Request) --------------------------------
  command::Stack& stack() { return session_.stack(); }
  // An English or "!TrafScript" line from `who` (the log's name) through
  // the dialogue of opts.client: {text, commands, ok, message, ask?,
  // addressed?, trace}.
  nlohmann::json command(const std::string& text, const std::string& who, const script::CommandOptions& opts = {});
  // The controller's decision on advisory `id`: {ok, message, ...command reply}.
  nlohmann::json decide(int id, bool accept, const std::string& who);
  void set_auto(bool on);
  void log(const std::string& who, const std::string& text);

 private:
  struct Advisory {
    int id = 0;
    double simt = 0;           // [s] when it was given
    std::string text;          // English
    std::string status;        // pending, accepted, rejected, expired
    std::string decided_by;    // controller, auto
    std::string outcome;       // TrafScript run, or why nothing ran
  };
  struct Pending {
    Request fn;
    std::shared_ptr<std::promise<nlohmann::json>> done;
  };

  void run();
  // command() without the JSON: a session error comes back as a reply with
  // ok = false and the error as its message.
  script::CommandReply run_command(const std::string& text, const std::string& who,
                                   const script::CommandOptions& opts);
  void advance(double wall_s);
  void log_events(const std::vector<script::SessionEvent>& events);
  void tick_teammate();
  void advise(const std::string& english);
  void execute(Advisory& a, const std::string& who);
  void publish();

  script::ServeSession& session_;
  LiveOptions options_;
  Teammate* teammate_;

  // Owner-thread state.
  std::deque<nlohmann::json> log_;
  std::deque<Advisory> advisories_;
  uint64_t log_seq_ = 0;
  int next_advisory_ = 1;
  bool auto_ = false;
  double owed_ = 0;  // [s] sim time the running clock owes (negative: ahead by part of a step)

  mutable std::mutex mu_;
  mutable std::condition_variable wake_;       // owner: a request arrived or stop
  mutable std::condition_variable published_;  // readers: a new state
  std::deque<Pending> queue_;
  bool stop_ = false;
  uint64_t version_ = 0;
  std::shared_ptr<const std::string> state_;
  std::thread thread_;
};

}  // namespace squawk::serve
