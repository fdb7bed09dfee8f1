#include "serve/live_sim.h"

#include <algorithm>

#include "script/reply_fields.h"
#include "serve/fields_json.h"
#include "serve/state_json.h"

namespace squawk::serve {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : sep) + s;
  return out;
}

}  // namespace

LiveSim::LiveSim(script::ServeSession& session, LiveOptions options, Teammate* teammate)
    : session_(session), options_(options), teammate_(teammate), auto_(options.auto_advisories) {
  publish();
}

LiveSim::~LiveSim() { stop(); }

void LiveSim::start() { thread_ = std::thread([this] { run(); }); }

void LiveSim::stop() {
  {
    std::lock_guard lock(mu_);
    stop_ = true;
  }
  wake_.notify_all();
  published_.notify_all();
  if (thread_.joinable()) thread_.join();
}

bool LiveSim::stopping() const {
  std::lock_guard lock(mu_);
  return stop_;
}

Result<json> LiveSim::call(Request fn, std::chrono::milliseconds timeout) {
  auto done = std::make_shared<std::promise<json>>();
  auto answer = done->get_future();
  {
    std::lock_guard lock(mu_);
    if (stop_) return Status::unavailable("the server is stopping");
    if (queue_.size() >= options_.max_queue)
      return Status::unavailable("too many requests waiting (" + std::to_string(queue_.size()) + "); try again");
    queue_.push_back({std::move(fn), std::move(done)});
  }
  wake_.notify_one();
  if (answer.wait_for(timeout) != std::future_status::ready)
    return Status::timeout("no answer within " + std::to_string(timeout.count()) + " ms");
  return answer.get();
}

std::pair<uint64_t, std::shared_ptr<const std::string>> LiveSim::state() const {
  std::lock_guard lock(mu_);
  return {version_, state_};
}

std::pair<uint64_t, std::shared_ptr<const std::string>> LiveSim::wait_state(uint64_t after,
                                                                           std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mu_);
  published_.wait_for(lock, timeout, [&] { return stop_ || version_ > after; });
  return {version_, state_};
}

void LiveSim::run() {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / options_.publish_hz));
  auto last = Clock::now();
  auto next = last + period;
  while (true) {
    std::deque<Pending> work;
    {
      std::unique_lock lock(mu_);
      wake_.wait_until(lock, next, [&] { return stop_ || !queue_.empty(); });
      if (stop_) break;
      work.swap(queue_);
    }
    for (auto& p : work) {
      json result;
      try {
        result = p.fn(*this);
      } catch (const std::exception& e) {
        result = {{"ok", false}, {"message", std::string("internal error: ") + e.what()}};
      }
      publish();
      p.done->set_value(std::move(result));
      session_.collect_after_reply();  // (the HTTP thread sends the reply meanwhile)
    }
    const auto now = Clock::now();
    if (now < next) continue;
    advance(std::chrono::duration<double>(now - last).count());
    last = now;
    tick_teammate();
    publish();
    session_.collect_after_reply();  // (an advisory executed automatically translates)
    next += period;
    if (next < now) next = now + period;
  }
  std::lock_guard lock(mu_);
  for (auto& p : queue_) p.done->set_value({{"ok", false}, {"message", "the server is stopping"}});
  queue_.clear();
}

void LiveSim::advance(double wall_s) {
  const sim::Simulation& sim = stack().sim();
  double tick_s = wall_s;
  if (sim.run_state() == sim::RunState::kOp && !sim.fast()) {
    // session:tick moves by whole steps; the sim time owed carries over so
    // that a step longer than a tick (DT 5 at real time) still comes.
    owed_ = std::min(owed_ + wall_s * stack().dtmult(), options_.max_owed_s);
    if (owed_ < 0.5 * sim.dt()) return;
    tick_s = owed_ / stack().dtmult();
  } else {
    owed_ = 0;
  }
  const double t0 = sim.simt();
  auto events = session_.tick(tick_s);
  if (!events) {
    log("sim", "error: " + events.status().message());
    return;
  }
  if (sim.run_state() == sim::RunState::kOp && !sim.fast()) owed_ -= sim.simt() - t0;
  log_events(*events);
}

void LiveSim::log_events(const std::vector<script::SessionEvent>& events) {
  for (const auto& e : events) log(e.kind == "echo" || e.kind == "failure" ? "scenario" : "sim", e.text);
}

void LiveSim::log(const std::string& who, const std::string& text) {
  log_.push_back({{"seq", ++log_seq_}, {"simt", stack().sim().simt()}, {"who", who}, {"text", text}});
  // Decisions stay longest: the oldest entry of the simulation, autopilot or
  // scenario goes first, the controller's, teammate's and auto's only when
  // nothing else is left.
  while (log_.size() > options_.log_shown) {
    auto it = std::find_if(log_.begin(), log_.end(), [](const json& e) {
      const std::string& w = e["who"].get_ref<const std::string&>();
      return w == "sim" || w == "autopilot" || w == "scenario";
    });
    log_.erase(it == log_.end() ? log_.begin() : it);
  }
}

json LiveSim::command(const std::string& text, const std::string& who, const script::CommandOptions& opts) {
  return fields_json(script::fields::kCommandReply, run_command(text, who, opts));
}

script::CommandReply LiveSim::run_command(const std::string& text, const std::string& who,
                                          const script::CommandOptions& opts) {
  auto r = session_.command(text, opts);
  if (!r) {
    log(who, text + "  -> error: " + r.status().message());
    script::CommandReply failed;
    failed.text = text;
    failed.message = r.status().message();
    return failed;
  }
  std::string entry = r->addressed.empty() ? r->text : "(" + r->addressed + ") " + r->text;
  if (!r->commands.empty() && r->text != "!" + r->commands.front()) entry += "  -> " + join(r->commands, " ; ");
  if (!r->ask.empty())
    entry += "  ? " + r->ask;
  else if (!r->ok)
    entry += "  -> error: " + r->message;
  else if (!r->message.empty())
    entry += "  -> " + r->message;
  log(who, entry);
  log_events(r->events);
  return std::move(*r);
}

void LiveSim::tick_teammate() {
  if (!teammate_) return;
  auto out = teammate_->tick(stack());
  if (!out) {
    log("teammate", "error: " + out.status().message());
    return;
  }
  for (const auto& n : out->notes) log("autopilot", n);
  for (const auto& a : out->advisories) advise(a);
}

void LiveSim::advise(const std::string& english) {
  for (auto& a : advisories_)
    if (a.status == "pending") {
      a.status = "expired";
      log("teammate", "advisory " + std::to_string(a.id) + " expired undecided");
    }
  Advisory a{next_advisory_++, stack().sim().simt(), english, "pending", "", ""};
  log("teammate", "advisory " + std::to_string(a.id) + ": \"" + english + "\"");
  advisories_.push_back(a);
  while (advisories_.size() > options_.advisories_shown) advisories_.pop_front();
  if (auto_) execute(advisories_.back(), "auto");
}

void LiveSim::execute(Advisory& a, const std::string& who) {
  a.decided_by = who;
  const script::CommandOptions advisory{"advisories", ""};  // a dialogue of their own
  const script::CommandReply r = run_command(a.text, who, advisory);
  a.status = "accepted";
  if (!r.ask.empty()) {
    run_command("cancel", who, advisory);  // a later advisory must not be read as the answer
    a.outcome = "not executed: the translator asked \"" + r.ask + "\"";
  } else {
    a.outcome =
        (r.ok ? "" : "failed: ") + join(r.commands, " ; ") + (r.ok ? "" : " (" + r.message + ")");
  }
}

json LiveSim::decide(int id, bool accept, const std::string& who) {
  auto it = std::find_if(advisories_.begin(), advisories_.end(), [&](const Advisory& a) { return a.id == id; });
  if (it == advisories_.end()) return {{"ok", false}, {"message", "no advisory " + std::to_string(id)}};
  if (it->status != "pending")
    return {{"ok", false}, {"message", "advisory " + std::to_string(id) + " is already " + it->status}};
  if (accept) {
    log(who, "accepted advisory " + std::to_string(id));
    execute(*it, who);
  } else {
    it->status = "rejected";
    it->decided_by = who;
    log(who, "rejected advisory " + std::to_string(id));
  }
  return {{"ok", true}, {"id", id}, {"status", it->status}, {"outcome", it->outcome}};
}

void LiveSim::set_auto(bool on) {
  auto_ = on;
  log("controller", std::string("automatic execution of advisories ") + (on ? "on" : "off"));
}

void LiveSim::publish() {
  json s = state_json(stack());
  s["log"] = json(log_);
  json adv = json::array();
  for (const auto& a : advisories_)
    adv.push_back({{"id", a.id}, {"simt", a.simt}, {"text", a.text}, {"status", a.status},
                   {"decided_by", a.decided_by}, {"outcome", a.outcome}});
  s["advisories"] = std::move(adv);
  s["auto"] = auto_;
  s["teammate"] = teammate_ != nullptr;
  // Log lines may quote scenario bytes that are not UTF-8 (written as U+FFFD).
  auto text = std::make_shared<const std::string>(s.dump(-1, ' ', false, json::error_handler_t::replace));
  {
    std::lock_guard lock(mu_);
    state_ = std::move(text);
    ++version_;
  }
  published_.notify_all();
}

}  // namespace squawk::serve
