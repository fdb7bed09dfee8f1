// Scenario files (Lua) -> environment and learner configs, Lua reward
// functions, and the train/eval command line.
#include <doctest/doctest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/files.h"
#include "env/horizontal_cr.h"
#include "script/scenario.h"

using namespace squawk;

namespace {

std::string write_temp(const char* name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string repo(const char* rel) { return std::string(SQUAWK_TEST_DATA) + "/../../" + rel; }

std::string run(const std::string& cmd) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return out;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) out += buf;
  pclose(p);
  return out;
}

}  // namespace

TEST_CASE("the shipped paper scenario sets the paper's training and evaluation settings") {
  auto s = script::load_scenario(repo("scenarios/horizontal_cr.lua"), {});
  REQUIRE_MESSAGE(s, s.status().message());
  CHECK(s->train_env.rules == env::Rules::kPaper);
  CHECK(s->train_env.tlos.lo == 120);
  CHECK(s->train_env.tlos.hi == 1000);
  CHECK(s->train_env.lookahead == 300);
  CHECK(s->eval_env.tlos.lo == 300);
  CHECK(s->eval_env.lookahead == 600);
  CHECK(s->train_env.weights.w_i == 0.4);
  CHECK(s->train_env.weights.w_d == -0.005);
  CHECK(s->train_env.weights.w_h == -0.01);
  CHECK(s->train_env.zone_radius == doctest::Approx(9260));
  CHECK(s->policy.action_values == std::vector<double>{-1, -0.5, 0, 0.5, 1});
  CHECK(s->eval_episodes == 1000);
  CHECK(s->policy.mirror.empty());
  auto m = script::load_scenario(
      write_temp("squawk_test_mirror.lua", "return { env = { speed_cap_ms = 0 }, policy = { mirror = true } }"), {});
  REQUIRE_MESSAGE(m, m.status().message());
  REQUIRE(m->policy.mirror.offset.size() == 28);
  CHECK(m->policy.mirror.offset[24] == 2.0f);  // y_difference_speed[1]: 2 x 150 m/s / 150 m/s
  auto g = script::load_scenario(repo("scenarios/horizontal_cr_gym.lua"), {});
  REQUIRE_MESSAGE(g, g.status().message());
  CHECK(g->train_env.rules == env::Rules::kGym);
  CHECK(g->policy.head == "gaussian");
  CHECK(g->train_env.limits.speed_cap == 89);
  CHECK_FALSE(s->train_env.weights.intrusion_at_substeps);
  // The training variant requires the paper scenario beside it and changes one key.
  auto v = script::load_scenario(repo("scenarios/horizontal_cr_substep.lua"), {});
  REQUIRE_MESSAGE(v, v.status().message());
  CHECK(v->train_env.weights.intrusion_at_substeps);
  CHECK(v->eval_env.weights.intrusion_at_substeps);
  CHECK(v->train_env.tlos.lo == 120);
  CHECK(v->eval_env.lookahead == 600);
}

TEST_CASE("the train table sets the learner, minibatches included") {
  auto s = script::load_scenario(
      write_temp("squawk_test_train.lua",
                 "return { train = { estimator = 'ppo', epochs = 3, minibatches = 4, clip = 0.1 } }"),
      {});
  REQUIRE(s);
  CHECK(s->train.estimator == "ppo");
  CHECK(s->train.epochs == 3);
  CHECK(s->train.minibatches == 4);
  CHECK(s->train.clip == 0.1);
  auto bad = script::load_scenario(
      write_temp("squawk_test_train.lua", "return { train = { minibatches = 0 } }"), {});
  REQUIRE_FALSE(bad);
  CHECK(bad.status().message().find("minibatches") != std::string::npos);
}

TEST_CASE("a Lua reward function replaces the built-in reward") {
  const std::string path = write_temp("squawk_test_reward.lua",
                                      "return { rules = 'paper', env = { lookahead_s = 600 },\n"
                                      "  reward = function(f) return f.intrusions > 0 and -7 or 1 end }\n");
  auto s = script::load_scenario(path, {});
  REQUIRE_MESSAGE(s, s.status().message());
  REQUIRE(s->lua_reward);
  auto e = env::HorizontalCrEnv::make(s->train_env);
  REQUIRE(e);
  Rng rng(3);
  bool ask = e->reset(rng);
  while (ask) {
    e->step(0.0);
    ask = !e->done();
  }
  // Every env step earned 1 or -7: the return is steps - 8 k for a whole k.
  const double k = (e->stats().steps - e->stats().total_reward) / 8.0;
  CHECK(k == doctest::Approx(std::round(k)));
  CHECK(e->stats().total_reward != 0.0);
  CHECK(s->reward_error().is_ok());

  const std::string bad = write_temp("squawk_test_reward_bad.lua",
                                     "return { reward = function(f) return 'x' end }\n");
  auto b = script::load_scenario(bad, {});
  REQUIRE(b);
  auto be = env::HorizontalCrEnv::make(b->train_env);
  REQUIRE(be);
  Rng rng2(1);
  if (be->reset(rng2)) be->step(0.0);
  CHECK_FALSE(b->reward_error().is_ok());
  CHECK(b->reward_error().message().find("expected a number") != std::string::npos);
}

TEST_CASE("scenario errors name the culprit") {
  struct Case {
    const char* lua;
    std::vector<const char*> says;
  };
  const Case cases[] = {
      {"return { env = { tlos = {1, 2} } }", {"unknown key 'tlos'"}},
      {"return { env = { tlos_s = {900, 100} } }", {"tlos"}},
      {"return { rules = 'atc' }", {"'rules'"}},
      {"return { reward = { intrusion_at = 'always' } }", {"'reward.intrusion_at' is 'always'"}},
      {"return { policy = { mirror = 'yes' } }", {"'policy.mirror' is a string: expected true or false"}},
      // The default fleet limits cap the ownship at 89 m/s: its speed changes, so no exact mirror.
      {"return { policy = { mirror = true } }", {"policy.mirror", "speed_cap 89"}},
      {"return 42", {"expected a table"}},
      {"return {", {"squawk_test_error.lua:1"}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.lua);
    auto s = script::load_scenario(write_temp("squawk_test_error.lua", c.lua), {});
    REQUIRE_FALSE(s);
    for (const char* text : c.says) CHECK(s.status().message().find(text) != std::string::npos);
  }
  CHECK(script::load_scenario("/nonexistent/x.lua", {}).status().code() == Code::kNotFound);
}

TEST_CASE("squawk eval --json prints Table 3's columns and the action histogram; bad usage exits 2") {
  const std::string bin = SQUAWK_BINARY;
  const std::string scen = repo("scenarios/horizontal_cr.lua");
  const std::string out = run(bin + " eval " + scen + " --policy zero --episodes 40 --seed 3 --json 2>&1");
  auto j = nlohmann::json::parse(out, nullptr, false);
  REQUIRE_MESSAGE(!j.is_discarded(), out);
  CHECK(j.at("episodes") == 40);
  // Never turning: every decision in the 0 bin.
  CHECK(j.at("decisions").get<long long>() > 0);
  CHECK(j.at("actions").at("0") == j.at("decisions"));
  CHECK(j.at("actions").at("0.5") == 0);
  CHECK(j.at("most_frequent_share").get<double>() == 1.0);
  CHECK(j.at("success_rate").get<double>() >= 0.0);
  CHECK(j.at("success_rate").get<double>() <= 1.0);
  CHECK(j.contains("mean_reward"));
  CHECK(j.contains("std_reward"));
  // Same seed, same numbers.
  CHECK(run(bin + " eval " + scen + " --policy random --episodes 30 --seed 5 --json") ==
        run(bin + " eval " + scen + " --policy random --episodes 30 --seed 5 --json"));
  const int bad_policy = std::system((bin + " eval " + scen + " --policy nope > /dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(bad_policy) == 2);
  const int no_out = std::system((bin + " train " + scen + " > /dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(no_out) == 2);
}
