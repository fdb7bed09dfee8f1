// squawk translate / squawk eval-translate: both run the Lua translation
// graph (scripts/translate/graph.lua) through script::run_translation_graph,
// in every mode; there is no other translator.
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "command/stack.h"
#include "llm/llm_config.h"
#include "script/translate_graph.h"
#include "translate/corpus.h"
#include "translate/stack_world.h"

namespace squawk::app {

namespace {

Result<std::string> mode_of(const Args& args) {
  std::string mode = args.get_or("--mode", "offline");
  if (mode != "offline" && mode != "single" && mode != "multi")
    return Status::invalid("--mode must be offline, single or multi, not '" + mode + "'");
  return mode;
}

// single and multi need an LLM server: refused up front (never a silent
// offline translation) when SQUAWK_LLM_URL is not set or the configuration
// does not validate (no SQUAWK_LLM_MODEL, a bad URL).
Status check_llm_for(const std::string& mode) {
  if (mode == "offline") return Status::ok();
  const char* url = std::getenv("SQUAWK_LLM_URL");
  if (url && *url) return llm::config_from_env().status();
  return Status::unavailable("--mode " + mode + " needs an LLM server: set SQUAWK_LLM_URL (http://host:11434 for "
                             "Ollama, a URL ending in /v1 for an OpenAI-compatible server) and SQUAWK_LLM_MODEL, "
                             "or use --mode offline");
}

nlohmann::json result_json(const translate::Translation& tr) {
  nlohmann::json j;
  if (tr.asked())
    j["ask"] = tr.ask;
  else if (!tr.error.empty())
    j["error"] = tr.error;
  else
    j["output"] = tr.text();
  if (!tr.note.empty()) j["note"] = tr.note;
  return j;
}

// One JSON line per case: {"id","output"} | {"id","ask"} | {"id","error"}, with "note" when
// something said is not simulated.
// A graph that fails to run (not a case it cannot translate) stops it.
Status print_jsonl(script::Vm& vm, const std::vector<translate::CorpusCase>& cases, const std::string& mode) {
  for (const auto& c : cases) {
    auto tr = script::run_translation_graph(vm, c.utterance, {mode, c.setup, nullptr});
    if (!tr) return tr.status().with_context(c.id);
    nlohmann::json j = result_json(*tr);
    j["id"] = c.id;
    // Corpus ids and text may hold bytes that are not UTF-8: written as U+FFFD.
    std::printf("%s\n", j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
    (void)script::collect_after_reply(vm);  // (the line is written)
  }
  return Status::ok();
}

}  // namespace

int cmd_translate(const ArgV& argv) {
  auto args = Args::parse(argv, with_vm_flags({{"--scenario", "--setup", "--tsv", "--mode"}, {"--jsonl"}}));
  if (!args) return usage_error("translate", args.status().message());
  auto mode = mode_of(*args);
  if (!mode) return usage_error("translate", mode.status().message());
  if (Status st = check_llm_for(*mode); !st.is_ok()) return failure(st);
  auto opts = vm_options(*args);
  if (!opts) return usage_error("translate", opts.status().message());
  script::Vm vm(*opts);
  if (auto tsv = args->get("--tsv")) {
    if (!args->positional().empty()) return usage_error("translate", "give either TEXT or --tsv CORPUS.tsv");
    auto cases = translate::read_corpus(*tsv);
    if (!cases) return failure(cases.status());
    if (Status st = print_jsonl(vm, *cases, *mode); !st.is_ok()) return failure(st);
    return kExitOk;
  }
  if (args->positional().size() != 1) return usage_error("translate", "expected one quoted TEXT");
  command::Stack stack;
  if (!opts->navdata_dir.empty()) {
    auto db = command::NavDb::load_cached(opts->navdata_dir);
    if (!db) return failure(db.status());
    stack.set_navdb(*db);
  }
  if (auto scn = args->get("--scenario")) {
    if (Status st = check_scn_file(*scn, false); !st.is_ok()) return usage_error("translate", "--scenario: " + st.message());
    Status st = stack.load_scenario(*scn);
    if (!st.is_ok()) return failure(st);
    stack.process_due();
  }
  if (auto setup = args->get("--setup")) {
    Status st = translate::setup_stack(stack, *setup);
    if (!st.is_ok()) return failure(st);
  }
  auto tr = script::run_translation_graph(vm, args->positional()[0], {*mode, "", &stack});
  if (!tr) return failure(tr.status());
  if (args->has("--jsonl")) {
    std::printf("%s\n", result_json(*tr).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
  } else if (tr->error.empty()) {
    std::printf("%s\n", tr->text().c_str());
    // what squawk does not simulate, named (stdout keeps the commands alone)
    if (!tr->note.empty()) std::fprintf(stderr, "%s\n", tr->note.c_str());
  }
  // The graph validated the commands on a scratch copy of the traffic; an
  // error means nothing valid came out (said once, on stderr).
  if (!tr->error.empty()) {
    std::fprintf(stderr, "squawk translate: no valid command: %s\n", tr->error.c_str());
    return kExitFail;
  }
  return kExitOk;
}

int cmd_eval_translate(const ArgV& argv) {
  auto args = Args::parse(argv, with_vm_flags({{"--mode"}, {"--failures", "--json", "--no-verify"}}));
  if (!args) return usage_error("eval-translate", args.status().message());
  if (args->positional().size() != 1) return usage_error("eval-translate", "expected one CORPUS.tsv");
  auto mode = mode_of(*args);
  if (!mode) return usage_error("eval-translate", mode.status().message());
  const std::string path = args->positional()[0];
  auto cases = translate::read_corpus(path);
  if (!cases) return failure(cases.status());
  if (Status st = check_llm_for(*mode); !st.is_ok()) return failure(st);
  auto opts = vm_options(*args);
  if (!opts) return usage_error("eval-translate", opts.status().message());
  script::Vm vm(*opts);
  Status load_error;
  translate::EvalReport report = translate::evaluate(*cases, [&](const translate::CorpusCase& c) {
    auto tr = script::run_translation_graph(vm, c.utterance, {*mode, c.setup, nullptr, !args->has("--no-verify")});
    if (!tr.is_ok() && load_error.is_ok()) load_error = tr.status().with_context(c.id);
    return tr;
  });
  if (!load_error.is_ok()) return failure(load_error);
  if (args->has("--json")) {
    nlohmann::json j;
    j["corpus"] = path;
    j["mode"] = *mode;
    j["cases"] = report.cases;
    j["correct"] = report.correct;
    j["right"] = report.correct;
    j["asked"] = report.asked;
    j["wrong"] = report.wrong;
    j["accuracy"] = report.accuracy();
    for (const auto& c : report.categories)
      j["categories"].push_back({{"category", c.category}, {"cases", c.cases}, {"correct", c.correct},
                                 {"right", c.correct}, {"asked", c.asked}, {"wrong", c.wrong}});
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("%s", translate::format_report(report, path + " (mode " + *mode + ")").c_str());
  }
  if (args->has("--failures"))
    for (const auto& o : report.outcomes)
      if (!o.correct)
        std::printf("%s [%s] %s\n  expected: %s\n  got:      %s%s\n", o.id.c_str(), o.category.c_str(),
                    o.asked ? "asked" : "WRONG", o.expected.c_str(), o.asked ? "ASK " : "", o.produced.c_str());
  return kExitOk;
}

}  // namespace squawk::app
