// squawk rag: retrieval over the command documentation (search, eval).
#include <cstdio>

#include "app/cli.h"
#include "app/subcommands.h"
#include "command/registry.h"
#include "core/paths.h"
#include "core/text.h"
#include "rag/bm25.h"
#include "rag/corpus.h"
#include "rag/notes.h"
#include "rag/recall.h"
#include "script/translate_graph.h"

namespace squawk::app {

namespace {

// The registry documentation with the grammar's words (the documents the
// translation graph retrieves from), plus a notes file when given.
Result<rag::Bm25Index> build_index(const Args& args) {
  std::vector<rag::Document> extra;
  if (!args.has("--no-notes")) {
    script::Vm vm{script::VmOptions{}};
    SQUAWK_ASSIGN_OR_RETURN(extra, script::grammar_documents(vm));
  }
  if (auto path = args.get("--notes")) {
    SQUAWK_ASSIGN_OR_RETURN(auto notes, rag::read_notes(*path));
    extra.insert(extra.end(), notes.begin(), notes.end());
  }
  return rag::Bm25Index(rag::command_documents(command::Registry::instance(), extra));
}

}  // namespace

int cmd_rag(const ArgV& argv) {
  Args::Spec spec;
  spec.value_flags = {"--k", "--notes"};
  spec.bool_flags = {"--misses", "--no-notes", "--text"};
  auto args = Args::parse(argv, spec);
  if (!args) return usage_error("rag", args.status().message());
  const auto& pos = args->positional();
  if (pos.size() < 2) return usage_error("rag", "expected `rag search QUERY...` or `rag eval CORPUS.tsv`");
  auto k = args->get_int("--k", 5);
  if (!k || *k < 1) return usage_error("rag", "--k expects a positive integer");
  auto index = build_index(*args);
  if (!index) return failure(index.status());

  if (pos[0] == "search") {
    const std::string query = text::join({pos.begin() + 1, pos.end()}, " ");
    for (const auto& h : index->search(query, static_cast<size_t>(*k))) {
      const auto& d = index->documents()[h.doc];
      std::printf("%-10s %7.3f\n", d.command.c_str(), h.score);
      if (args->has("--text")) std::printf("%s\n\n", d.text.c_str());
    }
    return kExitOk;
  }
  if (pos[0] == "eval") {
    auto cases = rag::read_corpus(pos[1]);
    if (!cases) return failure(cases.status());
    const auto r = rag::evaluate_recall(*index, *cases, static_cast<size_t>(*k));
    if (args->has("--misses"))
      for (const auto& m : r.misses) std::printf("miss %s\n", m.c_str());
    std::printf("cases %zu scored, %zu ASK skipped, %zu with unknown commands skipped\n", r.scored,
                r.ask_cases, r.unknown_cases);
    std::printf("Recall@1 %.3f (%zu/%zu)\n", r.recall_at_1(), r.hits_at_1, r.scored);
    std::printf("Recall@%zu %.3f (%zu/%zu)\n", r.k, r.recall_at_k(), r.hits_at_k, r.scored);
    return kExitOk;
  }
  return usage_error("rag", "unknown action " + text::quoted(pos[0]) + " (expected search or eval)");
}

}  // namespace squawk::app
