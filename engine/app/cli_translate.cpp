// squawk translate / squawk eval-translate.
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "app/subcommands.h"
#include "app/vm_options.h"
#include "command/stack.h"
#include "core/files.h"
#include "script/translate_graph.h"
#include "translate/corpus.h"
#include "translate/offline_translator.h"
#include "translate/stack_world.h"

namespace squawk::app {

namespace {

// Prints one JSON line per case: {"id","output"} | {"id","ask"} | {"id","error"}.
void print_jsonl(const std::vector<translate::CorpusCase>& cases) {
  for (const auto& c : cases) {
    nlohmann::json j;
    j["id"] = c.id;
    auto tr = translate::translate_case_offline(c);
    if (!tr.is_ok())
      j["error"] = tr.status().message();
    else if (tr->asked())
      j["ask"] = tr->ask;
    else
      j["output"] = tr->text();
    std::printf("%s\n", j.dump().c_str());
  }
}

}  // namespace

int cmd_translate(const ArgV& argv) {
  auto args = Args::parse(argv, {{"--scenario", "--setup", "--tsv"}, {"--jsonl"}});
  if (!args) return usage_error("translate", args.status().message());
  if (auto tsv = args->get("--tsv")) {
    if (!args->positional().empty()) return usage_error("translate", "give either TEXT or --tsv CORPUS.tsv");
    auto cases = translate::read_corpus(*tsv);
    if (!cases) return failure(cases.status());
    print_jsonl(*cases);
    return kExitOk;
  }
  if (args->positional().size() != 1) return usage_error("translate", "expected one quoted TEXT");
  command::Stack stack;
  if (auto scn = args->get("--scenario")) {
    Status st = stack.load_scenario(*scn);
    if (!st.is_ok()) return failure(st);
    stack.process_due();
  }
  if (auto setup = args->get("--setup")) {
    Status st = translate::setup_stack(stack, *setup);
    if (!st.is_ok()) return failure(st);
  }
  translate::StackWorld world(stack);
  auto tr = translate::translate_offline(args->positional()[0], &world);
  if (args->has("--jsonl")) {
    nlohmann::json j;
    if (tr.asked())
      j["ask"] = tr.ask;
    else
      j["output"] = tr.text();
    std::printf("%s\n", j.dump().c_str());
  } else {
    std::printf("%s\n", tr.text().c_str());
  }
  // With traffic given, the commands must run, in order, on a scratch copy of
  // it (a later command may need an earlier one: ADDWPT before DIRECT).
  const bool have_traffic = args->has("--scenario") || args->has("--setup");
  command::Stack scratch = stack;
  for (const auto& cmd : have_traffic ? tr.commands : std::vector<std::string>{}) {
    Status st = scratch.exec(cmd).status();
    if (!st.is_ok()) {
      std::fprintf(stderr, "squawk translate: produced command does not validate: %s\n", st.message().c_str());
      return kExitFail;
    }
  }
  return kExitOk;
}

int cmd_eval_translate(const ArgV& argv) {
  auto args = Args::parse(argv, with_vm_flags({{"--mode"}, {"--failures", "--json"}}));
  if (!args) return usage_error("eval-translate", args.status().message());
  if (args->positional().size() != 1) return usage_error("eval-translate", "expected one CORPUS.tsv");
  const std::string mode = args->get_or("--mode", "offline");
  if (mode != "offline" && mode != "single" && mode != "multi")
    return usage_error("eval-translate", "--mode must be offline, single or multi, not '" + mode + "'");
  const std::string path = args->positional()[0];
  auto cases = translate::read_corpus(path);
  if (!cases) return failure(cases.status());

  translate::EvalReport report;
  if (mode == "offline") {
    report = translate::evaluate(*cases, translate::translate_case_offline);
  } else {
    const char* url = std::getenv("SQUAWK_LLM_URL");
    if (!url || !*url) return failure(Status::unavailable("mode " + mode + " needs an LLM server: set SQUAWK_LLM_URL"));
    auto opts = vm_options(*args);
    if (!opts) return usage_error("eval-translate", opts.status().message());
    script::Vm vm(*opts);
    Status load_error;
    report = translate::evaluate(*cases, [&](const translate::CorpusCase& c) -> Result<translate::Translation> {
      auto tr = script::run_translation_graph(vm, c.utterance, mode, c.setup);
      if (!tr.is_ok() && tr.status().code() == Code::kNotFound) load_error = tr.status();
      return tr;
    });
    if (!load_error.is_ok()) return failure(load_error);
  }
  if (args->has("--json")) {
    nlohmann::json j;
    j["corpus"] = path;
    j["mode"] = mode;
    j["cases"] = report.cases;
    j["correct"] = report.correct;
    j["accuracy"] = report.accuracy();
    for (const auto& c : report.categories)
      j["categories"].push_back({{"category", c.category}, {"cases", c.cases}, {"correct", c.correct}});
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("%s", translate::format_report(report, path + " (mode " + mode + ")").c_str());
  }
  if (args->has("--failures"))
    for (const auto& o : report.outcomes)
      if (!o.correct)
        std::printf("%s [%s]\n  expected: %s\n  got:      %s%s\n", o.id.c_str(), o.category.c_str(), o.expected.c_str(),
                    o.asked ? "ASK " : "", o.produced.c_str());
  return kExitOk;
}

}  // namespace squawk::app
