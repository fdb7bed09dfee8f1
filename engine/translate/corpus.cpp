#include "translate/corpus.h"

#include <algorithm>
#include <cstdio>

#include "core/files.h"
#include "core/text.h"
#include "translate/scorer.h"
#include "translate/stack_world.h"

namespace squawk::translate {

Result<std::vector<CorpusCase>> parse_corpus(const std::string& tsv, const std::string& name) {
  std::vector<CorpusCase> cases;
  auto lines = text::split(tsv, '\n');
  for (size_t i = 1; i < lines.size(); ++i) {
    std::string line = lines[i];
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (text::trim(line).empty()) continue;
    auto f = text::split(line, '\t');
    if (f.size() < 5) {
      std::string msg = name;
      msg.append(":").append(std::to_string(i + 1)).append(": expected 5 tab-separated fields (id setup utterance expected category), got ").append(std::to_string(f.size()));
      return Status::corruption(msg);
    }
    cases.push_back({f[0], f[1], f[2], f[3], f[4]});
  }
  return cases;
}

Result<std::vector<CorpusCase>> read_corpus(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(std::string tsv, files::read(path));
  return parse_corpus(tsv, path);
}

EvalReport evaluate(const std::vector<CorpusCase>& cases, const CaseTranslator& translate) {
  EvalReport r;
  for (const auto& c : cases) {
    CaseOutcome o{c.id, c.category, "", c.expected, false, false};
    auto tr = translate(c);
    if (tr.is_ok()) {
      o.asked = tr->asked();
      o.produced = tr->text();
      o.correct = score_case(o.produced, o.asked, c.expected);
    } else {
      o.produced = "error: " + tr.status().message();
    }
    auto it = std::find_if(r.categories.begin(), r.categories.end(),
                           [&](const CategoryScore& s) { return s.category == c.category; });
    if (it == r.categories.end()) {
      r.categories.push_back({c.category, 0, 0});
      it = r.categories.end() - 1;
    }
    ++it->cases;
    ++r.cases;
    if (o.correct) {
      ++it->correct;
      ++r.correct;
    }
    r.outcomes.push_back(std::move(o));
  }
  return r;
}

Result<Translation> translate_case_offline(const CorpusCase& c) {
  command::Stack stack;
  SQUAWK_RETURN_IF_ERROR(setup_stack(stack, c.setup).with_context(c.id));
  StackWorld world(stack);
  return translate_offline(c.utterance, &world);
}

std::string format_report(const EvalReport& r, const std::string& title) {
  std::string out = title;
  out.append("\n");
  char line[160];
  std::snprintf(line, sizeof line, "%-12s %7s %8s %9s\n", "category", "cases", "correct", "accuracy");
  out.append(line);
  for (const auto& c : r.categories) {
    std::snprintf(line, sizeof line, "%-12s %7d %8d %8.1f%%\n", c.category.c_str(), c.cases, c.correct,
                  c.cases ? 100.0 * c.correct / c.cases : 0.0);
    out.append(line);
  }
  std::snprintf(line, sizeof line, "%-12s %7d %8d %8.1f%%\n", "overall", r.cases, r.correct, 100.0 * r.accuracy());
  out.append(line);
  return out;
}

}  // namespace squawk::translate
