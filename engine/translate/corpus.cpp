#include "translate/corpus.h"

#include <algorithm>
#include <cstdio>

#include "core/text.h"
#include "translate/scorer.h"

namespace squawk::translate {

EvalReport evaluate(const std::vector<CorpusCase>& cases, const CaseTranslator& translate) {
  EvalReport r;
  for (const auto& c : cases) {
    CaseOutcome o{c.id, c.category, "", c.expected, false, false};
    auto tr = translate(c);
    if (tr.is_ok() && !tr->on_yes.empty()) {
      // A yes/no question before destructive commands is right when the
      // request called for a question or when the yes runs exactly the
      // expected commands; proposing other commands counts as wrong.
      const std::string on_yes = text::join(tr->on_yes, " ; ");
      o.produced = tr->ask + " [yes runs: " + on_yes + "]";
      o.correct =
          score_case("", true, c.expected) || score_case(on_yes, false, c.expected, c.setup);
    } else if (tr.is_ok()) {
      o.asked = !tr->issued();
      // (nothing issued, no question: what was said is not simulated, and the note says so)
      o.produced = tr->issued() || tr->asked() || !tr->error.empty() ? tr->text() : tr->note;
      o.correct = score_case(tr->issued() ? o.produced : "", o.asked, c.expected, c.setup);
    } else {
      o.produced = "error: " + tr.status().message();
      o.asked = true;
    }
    auto it = std::find_if(r.categories.begin(), r.categories.end(),
                           [&](const CategoryScore& s) { return s.category == c.category; });
    if (it == r.categories.end()) {
      r.categories.push_back({c.category, 0, 0, 0, 0});
      it = r.categories.end() - 1;
    }
    ++it->cases;
    ++r.cases;
    if (o.correct) {
      ++it->correct;
      ++r.correct;
    } else if (o.asked) {
      ++it->asked;
      ++r.asked;
    } else {
      ++it->wrong;
      ++r.wrong;
    }
    r.outcomes.push_back(std::move(o));
  }
  return r;
}

std::string format_report(const EvalReport& r, const std::string& title) {
  std::string out = title;
  out.append("\n");
  char line[160];
  std::snprintf(line, sizeof line, "%-12s %6s %6s %6s %6s %8s %8s\n", "category", "cases", "right", "asked", "wrong",
                "right%", "wrong%");
  out.append(line);
  auto row = [&](const std::string& name, int cases, int right, int asked, int wrong) {
    std::snprintf(line, sizeof line, "%-12s %6d %6d %6d %6d %7.1f%% %7.1f%%\n", name.c_str(), cases, right, asked,
                  wrong, cases ? 100.0 * right / cases : 0.0, cases ? 100.0 * wrong / cases : 0.0);
    out.append(line);
  };
  for (const auto& c : r.categories) row(c.category, c.cases, c.correct, c.asked, c.wrong);
  row("overall", r.cases, r.correct, r.asked, r.wrong);
  return out;
}

}  // namespace squawk::translate
