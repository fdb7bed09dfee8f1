#include "translate/vocabulary.h"

#include "rag/edit_distance.h"

#include <algorithm>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace squawk::translate {
namespace {

const std::vector<std::string>& keyword_list() {
  static const std::vector<std::string> kWords = {
      "climb", "descend", "descent", "maintain", "altitude", "level", "flight", "heading", "turn", "left",
      "right", "speed", "knots", "reduce", "increase", "decrease", "delete", "remove", "waypoint", "waypoints",
      "direct", "directly", "proceed", "create", "aircraft", "destination", "origin", "vertical", "rate",
      "pause", "resume", "continue", "simulation", "scenario", "trail", "trails", "turbulence", "noise",
      "conflict", "conflicts", "detection", "resolution", "resolve", "separation", "minimum", "radius", "bank",
      "angle", "callsign", "degrees", "north", "south", "east", "west", "feet", "thousand", "hundred",
      "expedite", "cleared", "define", "route", "position", "reposition", "teleport", "move", "spawn",
      "generate", "place", "lateral", "navigation", "enable", "disable", "switch", "delete", "heavy", "mach",
      "seconds", "minutes", "minute", "second", "hours", "speedbird", "lufthansa", "descending", "climbing",
      "faster", "slower", "slow", "fast", "forward", "skip", "ahead", "timestep", "step", "seed", "random",
      "reset", "print", "echo", "load", "open", "freeze", "hold", "protected", "zone", "height", "look",
      "lookahead", "method", "potential", "voltage", "modified", "append", "insert", "add", "show", "hide",
      "list", "where", "details", "status", "lower", "raise", "cruise", "point", "fly", "towards", "around",
      "opposite", "direction", "same", "match", "double", "present", "current", "vectors", "vector", "traffic",
      "approach", "departure", "contact", "radar", "correction", "negative", "immediately", "until", "advised",
      "then", "when", "once", "reaches", "passes", "through", "below", "above", "fpm", "knot", "airspeed",
      "sink", "plan", "origin", "departed", "shift", "activate", "deactivate", "unpause", "start", "over",
      "real", "time", "half", "nautical", "miles", "percent", "degree", "latitude", "longitude", "named",
      "called", "type", "heading", "niner", "expect", "localizer", "final", "sequence", "spacing", "decimal",
      "brake", "limit", "custom", "fix", "visual", "runway", "cross", "descend", "altimeter", "maintained",
  };
  return kWords;
}

const std::unordered_set<std::string>& keyword_set() {
  static const std::unordered_set<std::string> kSet(keyword_list().begin(), keyword_list().end());
  return kSet;
}

// Words a typo is corrected to: instruction verbs, nouns and units whose
// misspelling would otherwise lose the instruction. Short everyday words
// ("load", "trail", "rate") are left out: speech recognition produces real
// words near them ("loan", "train", "rare") far more often than typists do.
const std::vector<std::string>& fix_targets() {
  static const std::vector<std::string> kTargets = {
      "climb", "descend", "descent", "maintain", "altitude", "heading", "speed", "knots", "reduce", "increase",
      "decrease", "delete", "remove", "waypoint", "direct", "create", "aircraft", "destination", "origin",
      "vertical", "simulation", "scenario", "turbulence", "conflict", "detection", "resolution", "separation",
      "radius", "angle", "callsign", "degrees", "feet", "thousand", "hundred", "expedite", "define", "teleport",
      "reposition", "lateral", "navigation", "enable", "disable", "seconds", "minutes", "timestep", "protected",
      "turn", "pause", "resume", "spawn", "generate", "latitude", "longitude", "minimum", "horizontal"};
  return kTargets;
}

}  // namespace

bool is_keyword(const std::string& w) { return keyword_set().count(w) > 0; }

bool is_filler(const std::string& w) {
  static const std::unordered_set<std::string> kFill = {"ah", "uh", "um", "er", "eh", "oh", "the", "a", "an",
                                                        "please", "pls", "okay", "ok", "yeah", "so", "and", "now"};
  return kFill.count(w) > 0;
}

std::string spell_fix(const std::string& w) {
  static const std::unordered_set<std::string> kCommon = {
      "stop", "them", "last", "want", "have", "from", "with", "what", "also", "back", "give", "make", "take",
      "need", "into", "onto", "down", "more", "less", "keep", "this", "that", "were", "will", "sure", "would",
      "should", "could", "their", "there", "these", "those", "about", "after", "again", "both", "each",
      "other", "some", "such", "than", "very", "your", "name", "time", "home", "over", "plus", "runs", "show", "send", "sent", "held", "lead"};
  if (w.size() <= 3 || is_keyword(w) || w.size() > 20 || kCommon.count(w)) return w;
  for (char c : w)
    if (c < 'a' || c > 'z') return w;
  const size_t limit = w.size() >= 7 ? 2 : 1;
  std::string best;
  size_t best_d = limit + 1;
  bool tie = false;
  for (const auto& k : fix_targets()) {
    if (k[0] != w[0] || k.size() + limit < w.size() || w.size() + limit < k.size()) continue;
    size_t d = rag::edit_distance(w, k);
    if (d < best_d) {
      best_d = d;
      best = k;
      tie = false;
    } else if (d == best_d && k != best) {
      tie = true;
    }
  }
  return best_d <= limit && !tie ? best : w;
}

}  // namespace squawk::translate
