#include "env/recorder.h"

#include <nlohmann/json.hpp>

namespace squawk::env {

namespace {
using nlohmann::json;

json aircraft(const Fleet& f, int i) { return json::array({f.lat(i), f.lon(i), f.hdg(i), f.tas(i)}); }

json intruders(const Fleet& f) {
  json a = json::array();
  for (int i = 1; i < static_cast<int>(f.size()); ++i) a.push_back(aircraft(f, i));
  return a;
}
}  // namespace

void JsonlRecorder::on_reset(const HorizontalCrEnv& env) {
  json j = {{"event", "reset"},
            {"episode", env.stats().index},
            {"rules", env.config().rules == Rules::kGym ? "gym" : "paper"},
            {"t", env.sim_time()},
            {"waypoint", json::array({env.waypoint_lat(), env.waypoint_lon()})},
            {"own", aircraft(env.fleet(), 0)},
            {"intruders", intruders(env.fleet())}};
  out_ << j.dump() << '\n';
}

void JsonlRecorder::on_step(const HorizontalCrEnv& env, const StepInfo& info) {
  json j = {{"event", "step"},  {"episode", env.stats().index}, {"t", env.sim_time()},
            {"agent", info.agent}, {"hdg_cmd", info.hdg_cmd}, {"reward", info.reward},
            {"intrusions", info.facts.intrusions},
            {"own", aircraft(env.fleet(), 0)}, {"intruders", intruders(env.fleet())}};
  if (info.agent) j["action"] = info.action;
  out_ << j.dump() << '\n';
}

void JsonlRecorder::on_end(const HorizontalCrEnv& env, const EpisodeStats& s) {
  json j = {{"event", "end"},          {"episode", s.index},       {"return", s.total_reward},
            {"success", s.success},    {"reached", s.reached},     {"truncated", s.truncated},
            {"steps", s.steps},        {"decisions", s.decisions}, {"intrusions", s.intrusions},
            {"t", env.sim_time()}};
  out_ << j.dump() << '\n';
}

}  // namespace squawk::env
