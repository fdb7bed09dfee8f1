#include "translate/offline_translator.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/text.h"
#include "core/units.h"
#include "translate/fuzzy.h"
#include "translate/lexer.h"
#include "translate/quantities.h"
#include "translate/references.h"
#include "translate/vocabulary.h"

namespace squawk::translate {
namespace {

// What a stretch of the utterance asks for; one TrafScript command each,
// except kMaintain and kZone, which the values decide.
enum class Intent {
  kInfer, kAlt, kSpd, kHdg, kVs, kMaintain, kCreate, kDelete, kAddWpt, kDefWpt, kDelWpt, kDirect, kDest,
  kOrig, kLnav, kVnav, kListRte, kPos, kMove, kBank, kHold, kOp, kFf, kDt, kDtMult, kReset, kSeed, kIc,
  kEcho, kAsas, kReso, kZone, kDtLook, kNoise, kTrail,
};

struct Trigger {
  Intent intent;
  size_t pos;
};

struct Segment {
  Intent intent = Intent::kInfer;
  size_t begin = 0;  // first token
  size_t trig = 0;   // token of the trigger word
  size_t end = 0;    // one past the last token
  bool then = false; // "then" stood before the trigger
};

std::string fmt(double v) { return text::fmt_double(v, 6); }
std::string fmt_int(double v) { return std::to_string(static_cast<long long>(std::llround(v))); }

std::string fmt_alt(double ft, bool fl) {
  if (fl && std::fmod(ft, 100.0) == 0.0) return std::string("FL").append(fmt_int(ft / 100.0));
  return fmt_int(ft);
}

std::string fmt_mach(double m) {
  std::string s = text::fmt_double(m, 3);
  return std::string("M").append(s.starts_with("0") ? s : std::string("0").append(s));
}

double wrap_heading(double h) {
  double r = std::fmod(h, 360.0);
  if (r <= 0.0) r += 360.0;
  return r;
}

double compass(const std::string& a, const std::string& b) {
  auto base = [](const std::string& w) -> double {
    if (w == "north") return 0;
    if (w == "east") return 90;
    if (w == "south") return 180;
    if (w == "west") return 270;
    return -1;
  };
  double x = base(a), y = base(b);
  if (x < 0) return -1;
  if (y < 0) return x == 0 ? 360 : x;
  if (x == 0 && y == 270) return 315;
  if (x == 0) return y / 2;
  if (x == 180) return (x + y) / 2;
  return -1;
}

class Parser {
 public:
  Parser(std::string_view utterance, const WorldView* world) : world_(world) {
    t_ = lex(utterance);
    for (auto& tok : t_)
      if (tok.kind == TokKind::kWord) tok.text = spell_fix(tok.text);
    used_.assign(t_.size(), false);
    refs_ = find_references(t_, world_, used_);
    if (world_) fleet_ = world_->aircraft();
  }

  Translation run() {
    size_t cond_end = 0;
    std::string cond = condition(cond_end);
    if (!ask_.empty()) return finish();
    parse(cond_end, t_.size());
    if (!cond.empty() && ask_.empty()) {
      if (out_.empty()) ask_ = "What should happen when the condition is met?";
      for (auto& c : out_) c = std::string(cond).append(" ").append(c);
    }
    return finish();
  }

 private:
  Translation finish() {
    Translation tr;
    if (ask_.empty() && out_.empty()) ask_ = pending_;
    if (!ask_.empty()) {
      tr.ask = ask_;
    } else if (out_.empty()) {
      tr.ask = "I did not understand that. Which command, aircraft and value do you mean?";
    } else {
      tr.commands = out_;
    }
    return tr;
  }

  // ---- token helpers ----
  bool word(size_t i, std::initializer_list<const char*> ws) const {
    if (i >= t_.size() || t_[i].kind != TokKind::kWord) return false;
    for (const char* w : ws)
      if (t_[i].text == w) return true;
    return false;
  }
  bool word_in(size_t b, size_t e, std::initializer_list<const char*> ws) const {
    for (size_t i = b; i < e && i < t_.size(); ++i)
      if (word(i, ws)) return true;
    return false;
  }
  // The first position in [b, e) holding one of `ws`, or e.
  size_t find_word(size_t b, size_t e, std::initializer_list<const char*> ws) const {
    for (size_t i = b; i < e && i < t_.size(); ++i)
      if (word(i, ws)) return i;
    return e;
  }

  std::vector<const Reference*> refs_in(size_t b, size_t e, RefKind kind) const {
    std::vector<const Reference*> r;
    for (const auto& ref : refs_)
      if (ref.kind == kind && ref.begin >= b && ref.begin < e) r.push_back(&ref);
    return r;
  }
  const AircraftView* state(const std::string& id) const {
    for (const auto& a : fleet_)
      if (text::iequals(a.id, id)) return &a;
    return nullptr;
  }

  // ---- conditions: "When AC01 reaches FL200, ..." ----
  std::string condition(size_t& rest) {
    size_t i = 0;
    while (i < t_.size() && t_[i].kind == TokKind::kWord && is_filler(t_[i].text)) ++i;
    if (!word(i, {"when", "once", "after"})) return "";
    size_t comma = i + 1;
    while (comma < t_.size() && !(t_[comma].kind == TokKind::kPunct && t_[comma].text == ",")) ++comma;
    if (comma >= t_.size()) return "";
    auto acids = refs_in(i, comma, RefKind::kAircraft);
    if (acids.empty()) return "";
    subject_ = acids.front()->name;
    rest = comma + 1;
    for (const auto& q : extract_quantities(t_, i, comma, used_)) {
      if (q.kind == QKind::kAlt) return "ATALT " + subject_ + " " + fmt_alt(q.value, q.flight_level);
      if (q.kind == QKind::kSpeed) return "ATSPD " + subject_ + " " + fmt_int(q.value);
      if (q.kind == QKind::kMach) return "ATSPD " + subject_ + " " + fmt_mach(q.value);
      if (q.kind == QKind::kPlain && q.value >= 1000) return "ATALT " + subject_ + " " + fmt_int(q.value);
    }
    ask_ = "At what altitude or speed should " + subject_ + " act?";
    return "";
  }

  // ---- triggers ----
  bool followed_by(size_t i, size_t span, std::initializer_list<const char*> ws) const {
    return word_in(i + 1, std::min(t_.size(), i + 1 + span), ws);
  }
  bool preceded_by(size_t i, size_t span, std::initializer_list<const char*> ws) const {
    return word_in(i >= span ? i - span : 0, i, ws);
  }
  bool number_at(size_t i) const { return i < t_.size() && !used_[i] && is_number_word(t_[i]); }
  bool has_type_or_aircraft_word(size_t b, size_t e) const {
    return !refs_in(b, e, RefKind::kType).empty() || word_in(b, e, {"aircraft", "plane", "airplane", "flight"});
  }
  bool sim_word_near(size_t i) const { return followed_by(i, 3, {"simulation", "sim", "simulator", "time"}); }

  std::optional<Intent> intent_at(size_t i) const {
    if (i >= t_.size() || used_[i] || t_[i].kind != TokKind::kWord) return std::nullopt;
    const std::string& w = t_[i].text;
    const size_t n = t_.size();
    if (preceded_by(i, 2, {"expect"})) return std::nullopt;  // "expect direct X" is not a clearance
    auto near = [&](size_t span, std::initializer_list<const char*> ws) { return followed_by(i, span, ws); };
    if (w == "climb" || w == "climbing" || w == "descend" || w == "descending" || w == "altitude" ||
        w == "cruise" || w == "altitudes")
      return preceded_by(i, 2, {"rate"}) ? std::nullopt : std::optional(Intent::kAlt);
    if (w == "descent" || w == "climbs") return preceded_by(i, 2, {"expedite", "rate"}) ? std::nullopt : std::optional(Intent::kAlt);
    if (w == "level" && word(i + 1, {"off"})) return Intent::kAlt;
    if (w == "lower" || w == "raise") return near(4, {"speed"}) ? Intent::kSpd : Intent::kAlt;
    if (w == "maintain" || w == "maintained") return Intent::kMaintain;
    if (w == "speed" || w == "spd" || w == "airspeed") {
      if (preceded_by(i, 1, {"vertical"})) return std::nullopt;
      if (sim_word_near(i) || (word(i + 1, {"up"}) && preceded_by(i, 3, {"simulation", "sim"})) ||
          preceded_by(i, 1, {"simulation", "sim"}))
        return Intent::kFf;
      if (preceded_by(i, 2, {"half", "double"})) return std::nullopt;
      return Intent::kSpd;
    }
    if (w == "slow" || w == "slower") return sim_word_near(i) ? Intent::kDtMult : Intent::kSpd;
    if (w == "faster" || w == "accelerate" || w == "decelerate") return Intent::kSpd;
    if ((w == "reduce" || w == "increase" || w == "decrease") && !near(4, {"altitude", "rate", "vertical"}))
      return Intent::kSpd;
    if (w == "heading" || w == "hdg" || w == "headings") return Intent::kHdg;
    if (w == "turn" || w == "switch") {
      size_t stop = i + 1;
      while (stop < n && stop < i + 5 && !is_number_word(t_[stop]) && !word(stop, {"left", "right", "heading"})) ++stop;
      if (word_in(i + 1, stop, {"on", "off"})) return std::nullopt;
      return w == "turn" ? std::optional(Intent::kHdg) : std::nullopt;
    }
    if ((w == "left" || w == "right") && number_at(i + 1) && !word(i + 2, {"degrees", "degree"}) &&
        !preceded_by(i, 2, {"turn", "heading"}))
      return Intent::kHdg;
    if ((w == "left" || w == "right") && word(i + 1, {"by"}) && number_at(i + 2) && !preceded_by(i, 2, {"turn"}))
      return Intent::kHdg;  // "further left by ten degrees"
    if ((w == "point" || w == "fly" || w == "towards" || w == "toward" || w == "head") &&
        near(4, {"north", "south", "east", "west"}))
      return Intent::kHdg;
    if (w == "around" && preceded_by(i, 3, {"turn"})) return std::nullopt;
    if (w == "vs" || w == "sink" || w == "expedite") return Intent::kVs;
    if (w == "vertical" && word(i + 1, {"speed", "rate"})) return Intent::kVs;
    if (w == "rate" && !preceded_by(i, 1, {"vertical"})) return Intent::kVs;
    if (w == "bank") return Intent::kBank;
    if (w == "define" || w == "defwpt") return Intent::kDefWpt;
    if (w == "create" && near(3, {"fix", "waypoint", "wpt"})) return Intent::kDefWpt;
    if (w == "create" || w == "spawn" || w == "generate" || w == "creat") return Intent::kCreate;
    if (w == "new" && (has_type_or_aircraft_word(i + 1, std::min(n, i + 3)))) return Intent::kCreate;
    if ((w == "add" || w == "append" || w == "insert" || w == "give") &&
        (near(4, {"waypoint", "wpt", "wp", "fix"}) ||
         (!refs_in(i + 1, std::min(n, i + 3), RefKind::kWaypoint).empty() && near(8, {"route", "plan"})) ||
         (word(i + 1, {"it"}) && near(6, {"route", "plan"}))))
      return Intent::kAddWpt;
    if ((w == "add" || w == "put" || w == "make" || w == "need" || w == "want") &&
        near(3, {"a", "an", "new", "second", "another"}) && has_type_or_aircraft_word(i + 1, std::min(n, i + 7)))
      return Intent::kCreate;
    if ((w == "remove" || w == "delete" || w == "del" || w == "skip") &&
        (near(2, {"waypoint", "wpt", "wp"}) ||
         (!refs_in(i + 1, std::min(n, i + 2), RefKind::kWaypoint).empty() && near(8, {"route", "plan"}))))
      return Intent::kDelWpt;
    if (w == "delete" || w == "del" || w == "remove" || w == "rid" || (w == "take" && near(5, {"out"})))
      return Intent::kDelete;
    if (w == "proceed" && near(3, {"heading"})) return std::nullopt;  // "proceed on heading 230"
    if (w == "direct" || w == "directly" || w == "dct" || w == "proceed" || w == "direct-to")
      return Intent::kDirect;
    if (w == "cleared" && world_ && !world_->waypoints().empty()) return Intent::kDirect;
    if (w == "destination" || (w == "fly" && word(i + 1, {"to"}))) return Intent::kDest;
    if (w == "origin" || w == "departed") return Intent::kOrig;
    if (w == "lnav" || (w == "lateral" && word(i + 1, {"navigation"}))) return Intent::kLnav;
    if (w == "vnav" || (w == "vertical" && word(i + 1, {"profile", "navigation"}))) return Intent::kVnav;
    if ((w == "route" || w == "waypoints" || w == "listrte") &&
        (preceded_by(i, 3, {"show", "list", "display", "what", "print"}) || w == "listrte"))
      return Intent::kListRte;
    if ((w == "where" && word(i + 1, {"is", "are", "'s"})) || w == "details" || w == "status" || w == "info" || w == "information") return Intent::kPos;
    if (w == "move" || w == "reposition" || w == "teleport" || w == "shift" || w == "place" || w == "relocate" ||
        (w == "put" && near(3, {"back"})))
      return Intent::kMove;
    if (w == "pause" || w == "hold" || w == "freeze" || (w == "stop" && sim_word_near(i))) return Intent::kHold;
    if (w == "restart" && sim_word_near(i)) return Intent::kReset;
    if ((w == "what" || w == "how") && near(4, {"altitude", "speed", "heading", "position", "level"}))
      return Intent::kPos;  // "What is the altitude of KLM123?"
    if (w == "unpause") return Intent::kOp;
    // "resume own navigation", "resume navigation", "back on your own navigation"
    if ((w == "resume" && near(3, {"navigation", "nav", "route"})) || (w == "own" && word(i + 1, {"navigation"})))
      return Intent::kLnav;
    // "run the simulation for ten minutes" is fast-time for a while; without a duration it is OP.
    if ((w == "run" || w == "advance") && sim_word_near(i) && !near(7, {"real", "times", "faster", "x"}))
      return near(7, {"for", "minutes", "minute", "seconds", "second", "hours", "hour", "min", "sec"})
                 ? Intent::kFf
                 : Intent::kOp;
    if ((w == "continue" || w == "resume") && (i + 1 >= n || t_[i + 1].kind == TokKind::kPunct || sim_word_near(i) ||
                            word(i + 1, {"running", "and"})))
      return Intent::kOp;
    if (w == "real" && word(i + 1, {"time"})) {
      if (i > 0 && word(i - 1, {"x", "times"})) return Intent::kDtMult;
      return Intent::kOp;
    }
    if ((w == "fast" && word(i + 1, {"forward"})) || w == "ff" || w == "fastforward" ||
        (w == "skip" && word(i + 1, {"ahead", "forward"})))
      return Intent::kFf;
    if (w == "timestep" || w == "dt" || (w == "time" && word(i + 1, {"step"}))) return Intent::kDt;
    if (w == "reset" || (w == "start" && word(i + 1, {"over"})) || (w == "clear" && sim_word_near(i)))
      return Intent::kReset;
    if (w == "seed") return Intent::kSeed;
    if (w == "scenario" || w == "load" || w == "open" || w == "ic") return Intent::kIc;
    if (w == "print" || (w == "echo" && i + 1 < n && t_[i + 1].kind == TokKind::kQuoted)) return Intent::kEcho;
    if (w == "detection" || w == "asas" || w == "cdmethod" || w == "cd") return Intent::kAsas;
    if (w == "resolution" || w == "resolve" || w == "reso") return Intent::kReso;
    if (w == "separation" && !preceded_by(i, 2, {"minimum", "horizontal", "vertical", "lateral"}) &&
        !near(4, {"minimum", "nm", "nautical", "miles", "radius", "ft", "feet"}))
      return std::nullopt;  // "maintain visual separation" is no setting
    if (w == "protected" || w == "pz" || w == "separation" || w == "zoner" || w == "zonedh" || w == "radius" ||
        (w == "half" && word(i + 1, {"height"})))
      return Intent::kZone;
    if ((w == "look" && word(i + 1, {"ahead"})) || w == "lookahead" || w == "dtlook") return Intent::kDtLook;
    if (w == "turbulence" || w == "noise") return Intent::kNoise;
    if (w == "trail" || w == "trails") return Intent::kTrail;
    return std::nullopt;
  }

  static bool same_family(Intent a, Intent b) {
    auto alt = [](Intent x) { return x == Intent::kAlt || x == Intent::kMaintain; };
    return a == b || (alt(a) && alt(b));
  }

  // Three digits said one by one before the first instruction word, with no
  // cue of their own, are a heading whose "fly heading" was lost in
  // recognition ("... Flighting Two Seven Zero maintain one eight zero knots").
  void orphan_heading(const Segment& s) {
    if (s.trig == s.begin || s.intent == Intent::kHdg || s.intent == Intent::kInfer) return;
    for (const auto& q : extract_quantities(t_, s.begin, s.trig, used_)) {
      if (q.kind != QKind::kPlain || q.number.typed || q.number.groups != 3 || !q.number.leading_digit_word ||
          q.value > 360 || q.number.has_hundred || (q.begin > 0 && word(q.begin - 1, {"at"})))
        continue;
      // Only after a recognised callsign and a word of its own: digits right
      // after an unrecognised callsign may be the callsign's.
      const Reference* call = nullptr;
      for (const auto& r : refs_)
        if (r.kind == RefKind::kAircraft && r.end <= q.begin) call = &r;
      if (!call || q.begin <= call->end || t_[q.begin - 1].kind != TokKind::kWord || is_number_word(t_[q.begin - 1]))
        continue;
      auto ids = acids(s);
      if (ids.size() != 1) return;
      out_.push_back("HDG " + ids.front() + " " + fmt(wrap_heading(q.value)));
      for (size_t i = q.begin; i < q.end; ++i) used_[i] = true;
      return;
    }
  }

  // Intents that never merge with a neighbour of the same intent.
  static bool mergeable(Intent a) { return a != Intent::kCreate && a != Intent::kDelete; }
  static bool value_intent(Intent a) {
    return a == Intent::kAlt || a == Intent::kSpd || a == Intent::kHdg || a == Intent::kVs || a == Intent::kMaintain;
  }
  // Instructions that carry several values absorb the value words after them
  // ("create ... heading 090 at FL200 and 250 knots").
  static bool absorbs(Intent a) {
    return a == Intent::kCreate || a == Intent::kMove || a == Intent::kAddWpt || a == Intent::kDefWpt;
  }

  void parse(size_t b, size_t e) {
    std::vector<Trigger> trig;
    for (size_t i = b; i < e; ++i)
      if (auto in = intent_at(i)) trig.push_back({*in, i});
    std::vector<Segment> segs;
    if (trig.empty()) {
      segs.push_back({Intent::kInfer, b, b, e, false});
    } else {
      for (size_t k = 0; k < trig.size(); ++k) {
        bool then = word_in(k == 0 ? b : trig[k - 1].pos, trig[k].pos, {"then"});
        if (!segs.empty() && !then &&
            ((absorbs(segs.back().intent) && value_intent(trig[k].intent)) ||
             (segs.back().intent == Intent::kAlt && trig[k].intent == Intent::kVs && word(trig[k].pos, {"rate"}))))
          continue;
        if (!segs.empty() && segs.back().intent == Intent::kCreate && trig[k].intent == Intent::kCreate &&
            refs_in(segs.back().trig, trig[k].pos, RefKind::kAircraft).empty())
          continue;  // "make a new ...": one request
        bool alt_pair = (segs.empty() ? false
                                      : (segs.back().intent == Intent::kMaintain && trig[k].intent == Intent::kAlt) ||
                                            (segs.back().intent == Intent::kAlt && trig[k].intent == Intent::kMaintain)) &&
                        extract_quantities(t_, segs.back().trig, trig[k].pos, used_).empty();
        if (!segs.empty() && (segs.back().intent == trig[k].intent || alt_pair) && mergeable(trig[k].intent) &&
            !then) {
          if (trig[k].intent == Intent::kAlt) segs.back().intent = Intent::kAlt;
          continue;
        }
        if (!segs.empty()) segs.back().end = trig[k].pos;
        segs.push_back({trig[k].intent, segs.empty() ? b : trig[k].pos, trig[k].pos, e, then});
      }
      // Words before a segment's trigger that follow "and"/"," belong to it
      // ("... and turn it", "Switch on LNAV and VNAV for AC01" keeps "for AC01").
    }
    // A "correction" restarts the instruction it corrects: keep the last
    // segment of each intent after the last correction.
    size_t prev_out = out_.size();  // where the previous segment's commands start
    if (!segs.empty()) orphan_heading(segs.front());
    for (size_t k = 0; k < segs.size() && ask_.empty(); ++k) {
      // "descend and maintain four th- correction descend and maintain three
      // thousand": the corrected instruction replaces the one before it.
      if (k > 0 && word_in(segs[k - 1].trig, segs[k].trig, {"correction", "disregard"}) &&
          same_family(segs[k - 1].intent, segs[k].intent))
        out_.resize(prev_out);
      prev_out = out_.size();
      // "Status of BAW45? Altitude, speed, everything": a bare noun after a
      // handled instruction names what to show, not a new instruction.
      if (k > 0 && !out_.empty() && word(segs[k].trig, {"altitude", "speed", "heading", "airspeed"}) &&
          quantities(segs[k]).empty())
        continue;
      std::string before = last_cond_;
      last_cond_.clear();
      size_t n_before = out_.size();
      std::string at = at_altitude(segs[k]);
      handle(segs[k]);
      if (ask_.empty() && out_.size() > n_before) leftovers(segs[k]);
      if (!at.empty())
        for (size_t c = n_before; c < out_.size(); ++c) out_[c] = std::string(at).append(" ").append(out_[c]);
      // A value instruction said without its value next to other, complete
      // instructions ("turn left direct X", "... ten is a parallel climb") is
      // left out; it only becomes the question when nothing else was understood.
      if (!ask_.empty() && value_intent(segs[k].intent) && values_after_trigger(segs[k]) == 0) {
        if (pending_.empty()) pending_ = ask_;
        ask_.clear();
        continue;
      }
      if (segs[k].then && !before.empty() && out_.size() == n_before + 1 &&
          text::starts_with_ci(out_.back(), "SPD ") != text::starts_with_ci(before, "ATSPD")) {
        out_.back() = std::string(before).append(" ").append(out_.back());
      }
    }
  }

  // "at four thousand reduce speed to 210": a speed or heading instruction
  // that waits for an altitude. Returns "ATALT id alt" or "".
  std::string at_altitude(const Segment& s) {
    if (s.intent != Intent::kSpd && s.intent != Intent::kHdg) return "";
    size_t a = find_word(s.begin, s.trig, {"at"});
    if (a >= s.trig) return "";
    auto qs = extract_quantities(t_, a + 1, s.trig, used_);
    if (qs.empty() || qs.front().begin != a + 1 || qs.front().end != s.trig) return "";
    const Quantity& q = qs.front();
    if (q.kind != QKind::kAlt && !(q.kind == QKind::kPlain && (q.number.has_thousand || q.value >= 1000))) return "";
    auto ids = acids(s);
    if (ids.empty()) return "";
    return "ATALT " + ids.front() + " " + fmt_alt(q.value, q.flight_level);
  }

  // "AC02: heading 180, FL200, 250 kts": values with their own units after a
  // value instruction, of another kind and with no instruction word of their
  // own, are instructions too.
  void leftovers(const Segment& s) {
    if (s.intent != Intent::kHdg && s.intent != Intent::kAlt && s.intent != Intent::kSpd) return;
    auto ids = acids(s);
    if (ids.size() != 1) return;
    bool alt_done = s.intent == Intent::kAlt, spd_done = s.intent == Intent::kSpd;
    for (const auto& q : quantities(s)) {
      if (q.begin <= s.trig) continue;
      if (q.kind == QKind::kAlt && !alt_done && (q.flight_level || word(q.end - 1, {"ft", "feet", "foot"}))) {
        out_.push_back("ALT " + ids.front() + " " + fmt_alt(q.value, q.flight_level));
        alt_done = true;
      } else if ((q.kind == QKind::kSpeed || q.kind == QKind::kMach) && !spd_done) {
        out_.push_back("SPD " + ids.front() + " " + (q.kind == QKind::kMach ? fmt_mach(q.value) : fmt_int(q.value)));
        spd_done = true;
      }
    }
  }

  // ---- values ----
  std::vector<Quantity> quantities(const Segment& s) const { return extract_quantities(t_, s.begin, s.end, used_); }
  size_t values_after_trigger(const Segment& s) const {
    auto qs = quantities(s);
    return static_cast<size_t>(std::count_if(qs.begin(), qs.end(), [&](const Quantity& q) { return q.begin >= s.trig; }));
  }

  // +1 for up/more words, -1 for down/less words, 0 when none.
  int direction(const Segment& s) const {
    for (size_t i = s.begin; i < s.end; ++i) {
      if (word(i, {"climb", "up", "raise", "increase", "faster", "above", "higher", "accelerate", "climbing"})) return 1;
      if (word(i, {"descend", "down", "lower", "reduce", "decrease", "slow", "slower", "below", "descent",
                   "sink", "descending", "decelerate", "minus"}))
        return -1;
    }
    return 0;
  }

  int on_off(const Segment& s) const {
    size_t b = s.begin > 0 && word(s.begin - 1, {"off", "on"}) ? s.begin - 1 : s.begin;
    if (word_in(b, s.end, {"off", "disable", "deactivate", "hide", "stop", "don't", "dont", "without", "remove"}) ||
        word_in(s.begin, s.end, {"anymore", "longer"}))
      return 0;
    if (word_in(b, s.end, {"on", "enable", "activate", "show", "start", "use"})) return 1;
    return -1;
  }

  // Aircraft a segment talks about: those after its trigger, else before it,
  // else the utterance's subject, else the world's only aircraft.
  std::vector<std::string> acids(const Segment& s) {
    std::vector<std::string> ids;
    // With aircraft in the world, a name that matches none of them is noise
    // when another name does match.
    bool any_known = std::any_of(refs_.begin(), refs_.end(),
                                 [](const Reference& r) { return r.kind == RefKind::kAircraft && r.exists; });
    auto take = [&](size_t b, size_t e) {
      for (const auto* r : refs_in(b, e, RefKind::kAircraft))
        if ((r->exists || !any_known) && std::find(ids.begin(), ids.end(), r->name) == ids.end())
          ids.push_back(r->name);
    };
    take(s.trig, s.end);
    if (ids.empty()) take(s.begin, s.trig);
    if (ids.empty() && !subject_.empty()) ids.push_back(subject_);
    if (ids.empty()) {
      // an aircraft named later in the utterance ("Switch on LNAV and VNAV for AC01")
      for (const auto& r : refs_)
        if (r.kind == RefKind::kAircraft && r.begin >= s.end) {
          ids.push_back(r.name);
          break;
        }
    }
    if (ids.empty() && fleet_.size() == 1) ids.push_back(fleet_.front().id);
    if (!ids.empty()) subject_ = ids.front();
    return ids;
  }
  std::optional<std::string> acid(const Segment& s, const char* what) {
    auto ids = acids(s);
    if (ids.empty()) {
      ask_ = std::string("Which aircraft should ").append(what).append("? Please give its callsign.");
      return std::nullopt;
    }
    return ids.front();
  }
  void need(const std::string& question) {
    if (ask_.empty()) ask_ = question;
  }

  // A numeric value that grew out of range from a stutter or a misheard
  // word ("one four fourteen thousand", "one one six zero"): re-read from a
  // shorter run of its words, longest run first, preferring values that are
  // multiples of `step` (assigned speeds, headings and levels are round).
  std::optional<double> repaired(const Quantity& q, double lo, double hi, double step) const {
    if (q.value >= lo && q.value <= hi) return q.value;
    if (q.number.typed) return std::nullopt;
    const size_t b0 = q.number.begin, e0 = q.number.end;
    for (bool round_only : {true, false})
      for (size_t len = e0 - b0 - 1; len >= 1; --len)
        for (size_t b = b0; b + len <= e0; ++b) {
          std::vector<Token> part(t_.begin() + static_cast<long>(b), t_.begin() + static_cast<long>(b + len));
          auto n = read_number(part, 0);
          if (!n || n->end != part.size() || n->has_thousand != q.number.has_thousand) continue;
          if (n->value < lo || n->value > hi) continue;
          if (round_only && std::fmod(n->value, step) != 0.0) continue;
          return n->value;
        }
    return std::nullopt;
  }

  // Which candidate value counts: after "correction"/"disregard" the first
  // one after it; when the instruction word is repeated ("right heading 270
  // ah right heading 090") the last one; else the first.
  std::optional<Quantity> pick(const std::vector<Quantity>& c, const Segment& s, const char* repeated) const {
    if (c.empty()) return std::nullopt;
    size_t corr = s.end;
    for (size_t i = s.begin; i < s.end; ++i)
      if (word(i, {"correction", "disregard"})) corr = i;
    if (corr < s.end) {
      for (const auto& q : c)
        if (q.begin > corr) return q;
      return c.back();
    }
    size_t reps = 0;
    for (size_t i = s.begin; i < s.end; ++i)
      if (word(i, {repeated})) ++reps;
    return reps >= 2 ? c.back() : c.front();
  }

  // ---- handlers ----
  void handle(const Segment& s) {
    switch (s.intent) {
      case Intent::kInfer: return infer(s);
      case Intent::kAlt: return altitude(s);
      case Intent::kMaintain: return maintain(s);
      case Intent::kSpd: return speed(s);
      case Intent::kHdg: return heading(s);
      case Intent::kVs: return vspeed(s);
      case Intent::kCreate: return create(s);
      case Intent::kDelete: return remove(s);
      case Intent::kAddWpt: return add_waypoint(s);
      case Intent::kDefWpt: return define_waypoint(s);
      case Intent::kDelWpt: return delete_waypoint(s);
      case Intent::kDirect: return direct(s);
      case Intent::kDest: return dest_orig(s, "DEST");
      case Intent::kOrig: return dest_orig(s, "ORIG");
      case Intent::kLnav: return nav(s, "LNAV");
      case Intent::kVnav: return nav(s, "VNAV");
      case Intent::kListRte: return one_acid(s, "LISTRTE", "have its route listed");
      case Intent::kPos: return one_acid(s, "POS", "be shown");
      case Intent::kMove: return move(s);
      case Intent::kBank: return bank(s);
      case Intent::kHold: return out_.push_back("HOLD");
      case Intent::kOp: return out_.push_back("OP");
      case Intent::kReset: return out_.push_back("RESET");
      case Intent::kFf: return fast_forward(s);
      case Intent::kDt: return time_step(s);
      case Intent::kDtMult: return time_mult(s);
      case Intent::kSeed: return seed(s);
      case Intent::kIc: return scenario(s);
      case Intent::kEcho: return echo(s);
      case Intent::kAsas: return switch_cmd(s, "ASAS");
      case Intent::kReso: return resolution(s);
      case Intent::kZone: return zone(s);
      case Intent::kDtLook: return look_ahead(s);
      case Intent::kNoise: return switch_cmd(s, "NOISE");
      case Intent::kTrail: return switch_cmd(s, "TRAIL");
    }
  }

  void infer(const Segment& s) {
    auto qs = quantities(s);
    for (const auto& q : qs) {
      if (q.kind == QKind::kAlt || (q.kind == QKind::kPlain && q.number.has_thousand)) return altitude(s);
      if (q.kind == QKind::kSpeed || q.kind == QKind::kMach) return speed(s);
      if (q.kind == QKind::kHeading) return heading(s);
      if (q.kind == QKind::kVs) return vspeed(s);
      if (q.kind == QKind::kLat) return move(s);
      if (q.kind == QKind::kMult) return time_mult(s);
    }
    // Three digits said one by one with no other cue: a heading ("... flighting zero four zero").
    for (const auto& q : qs)
      if (q.kind == QKind::kPlain && !q.number.typed && q.number.groups == 3 && q.number.leading_digit_word &&
          q.value <= 360 && !q.number.has_hundred && !q.number.has_decimal)
        return heading(s);
    if (!acids(s).empty() && qs.empty() && refs_in(s.begin, s.end, RefKind::kAircraft).size() == 1 &&
        s.end - s.begin == 1)
      return one_acid(s, "POS", "be shown");
    need("I did not understand that. Which command, aircraft and value do you mean?");
  }

  void maintain(const Segment& s) {
    auto qs = quantities(s);
    for (const auto& q : qs) {
      if (q.begin < s.trig) continue;
      if (q.kind == QKind::kSpeed || q.kind == QKind::kMach) return speed(s);
      if (q.kind == QKind::kAlt) return altitude(s);
    }
    for (const auto& q : qs) {
      if (q.begin < s.trig) continue;
      if (q.kind == QKind::kAlt) return altitude(s);
      if (q.kind == QKind::kSpeed || q.kind == QKind::kMach) return speed(s);
      if (q.kind == QKind::kHeading) return heading(s);
      if (q.kind == QKind::kPlain) {
        // "maintain two five zero" is a speed; "maintain four thousand" an altitude.
        if (q.value >= 100 && q.value <= 400 && !q.number.has_thousand && !q.number.has_hundred) return speed(s);
        return altitude(s);
      }
    }
    if (word_in(s.trig, s.end, {"heading"})) return heading(s);
    altitude(s);
  }

  void altitude(const Segment& s) {
    auto ids = acids(s);
    if (ids.empty()) return need("Which aircraft should change altitude? Please give its callsign.");
    auto qs = quantities(s);
    std::optional<Quantity> rate;
    std::vector<Quantity> with_unit, plain;
    for (const auto& q : qs) {
      if (q.kind == QKind::kVs && !rate) rate = q;
      if (q.kind == QKind::kAlt) with_unit.push_back(q);
      if (q.kind == QKind::kPlain && q.begin >= s.trig) plain.push_back(q);
    }
    // "rate fifteen hundred": a plain number after "rate" is the vertical speed
    size_t rate_word = find_word(s.begin, s.end, {"rate"});
    for (auto* list : {&plain, &with_unit})
      for (auto it = list->begin(); !rate && rate_word < s.end && it != list->end(); ++it)
        if (it->begin > rate_word && !it->flight_level) {
          rate = *it;
          list->erase(it);
          break;
        }
    std::optional<Quantity> target = pick(with_unit.empty() ? plain : with_unit, s, "maintain");
    const AircraftView* now = state(ids.front());
    const std::string verb = direction(s) > 0 ? "climb" : direction(s) < 0 ? "descend" : "fly";
    if (word_in(s.begin, s.end, {"double"}) && now) {
      for (auto& id : ids) out_.push_back("ALT " + id + " " + fmt_int(units::m_to_ft(now->alt_m) * 2.0));
      return;
    }
    if (!target && rate) return vspeed(s);
    if (!target) return need("What altitude should " + ids.front() + " " + verb + " to?");
    Quantity q = *target;
    double ft = q.value;
    bool fl = q.flight_level;
    if (q.kind == QKind::kPlain && !q.number.typed && !q.number.has_thousand) {
      // a stutter: "one four fourteen" -> 14 (thousand)
      const std::string& d = q.number.digits;
      if (d.size() >= 4 && d.size() % 2 == 0 && d.substr(0, d.size() / 2) == d.substr(d.size() / 2))
        ft = std::stod(d.substr(0, d.size() / 2));
    }
    if (q.kind == QKind::kPlain) {
      if (ft < 100 && !q.number.typed) {
        ft *= 1000.0;  // "maintain niner (thousand)"
      } else if (ft >= 100 && ft < 1000 && !q.number.has_hundred) {
        ft *= 100.0;  // "climb three five zero": a flight level
        fl = true;
      }
    }
    if (!fl) {
      auto r = repaired(Quantity{q.kind, ft, q.begin, q.end, fl, q.by, q.to, q.turn, q.number}, 0.0, 60000.0, 100.0);
      if (!r) return need("Which altitude for " + ids.front() + "? I heard " + fmt_int(ft) + " ft.");
      if (*r < 100 && !q.number.typed) *r *= 1000.0;
      ft = *r;
    }
    // Relative: "by 2000 ft", "1000 ft from its present altitude", "one thousand feet below AC01".
    auto others = refs_in(s.begin, s.end, RefKind::kAircraft);
    bool below = word_in(s.begin, s.end, {"below", "under"}), above = word_in(s.begin, s.end, {"above", "over"});
    if ((below || above) && others.size() >= 2) {
      const AircraftView* ref = state(others.back()->name);
      if (!ref) return need("What is the altitude of " + others.back()->name + "?");
      double base = units::m_to_ft(ref->alt_m);
      out_.push_back("ALT " + ids.front() + " " + fmt_int(base + (above ? ft : -ft)));
      return;
    }
    bool relative = q.by || word_in(s.begin, s.end, {"present", "current", "by"});
    int dir = direction(s);
    if (!relative && now && !q.to && !fl && dir != 0) {
      double cur = units::m_to_ft(now->alt_m);
      if ((dir > 0 && ft <= cur - 50 && ft <= 5000 && !q.number.has_thousand) || (dir > 0 && ft < 3000 && cur > 10000))
        relative = true;
    }
    for (auto& id : ids) {
      std::string alt;
      if (relative) {
        const AircraftView* a = state(id);
        if (!a) return need("What is the current altitude of " + id + "?");
        double base = units::m_to_ft(a->alt_m);
        alt = fmt_int(base + (dir < 0 ? -ft : ft));
      } else {
        alt = fmt_alt(ft, fl);
      }
      std::string cmd = "ALT " + id + " " + alt;
      if (rate) cmd += " " + fmt_int(rate->value);
      out_.push_back(cmd);
      last_cond_ = "ATALT " + id + " " + alt;
    }
  }

  void speed(const Segment& s) {
    auto ids = acids(s);
    if (ids.empty()) return need("Which aircraft should change speed? Please give its callsign.");
    auto qs = quantities(s);
    std::vector<Quantity> with_unit, plain;
    for (const auto& q : qs) {
      if (q.kind == QKind::kSpeed || q.kind == QKind::kMach || q.kind == QKind::kPercent) with_unit.push_back(q);
      if (q.kind == QKind::kPlain && (q.begin >= s.trig || q.number.typed)) plain.push_back(q);
    }
    std::optional<Quantity> v = pick(with_unit.empty() ? plain : with_unit, s, "speed");
    // "Match AC02's speed to AC01" / "the same speed as AC01"
    auto refs = refs_in(s.begin, s.end, RefKind::kAircraft);
    if (!v && refs.size() >= 2 && word_in(s.begin, s.end, {"match", "same", "as"})) {
      const AircraftView* src = state(refs.back()->name);
      if (!src) return need("What is the speed of " + refs.back()->name + "?");
      out_.push_back("SPD " + refs.front()->name + " " +
                     (src->mach > 0 ? fmt_mach(src->mach) : fmt_int(units::ms_to_kt(src->cas_ms))));
      return;
    }
    if (!v) return need("What speed should " + ids.front() + " fly? Please give knots or a Mach number.");
    Quantity q = *v;
    int dir = direction(s);
    for (auto& id : ids) {
      std::string spd;
      if (q.kind == QKind::kMach || (q.kind == QKind::kPlain && q.value > 0 && q.value < 1)) {
        spd = fmt_mach(q.value);
      } else if (q.kind == QKind::kPercent || q.by || (word_in(s.begin, s.end, {"by"}) && q.value < 100)) {
        const AircraftView* a = state(id);
        if (!a || a->cas_ms <= 0) return need("What is the current speed of " + id + "?");
        double cur = units::ms_to_kt(a->cas_ms);
        double delta = q.kind == QKind::kPercent ? cur * q.value / 100.0 : q.value;
        spd = fmt_int(cur + (dir < 0 ? -delta : delta));
      } else {
        double kt = q.value;
        if (!q.number.typed && kt >= 10 && kt < 100 && q.number.groups == 2) kt *= 10.0;  // "speed one nine"
        auto r = repaired(Quantity{q.kind, kt, q.begin, q.end, false, false, false, 0, q.number}, 40.0, 700.0, 10.0);
        if (!r) return need("What speed should " + id + " fly? I heard " + fmt_int(kt) + ".");
        // Assigned speeds are multiples of 5 kt; a spoken odd last digit is a recognition error.
        if (!q.number.typed && std::fmod(*r, 5.0) != 0.0) *r = std::floor(*r / 10.0) * 10.0;
        spd = fmt_int(*r);
      }
      out_.push_back("SPD " + id + " " + spd);
      last_cond_ = "ATSPD " + id + " " + spd;
    }
  }

  void heading(const Segment& s) {
    auto ids = acids(s);
    if (ids.empty()) return need("Which aircraft should turn? Please give its callsign.");
    auto qs = quantities(s);
    std::vector<Quantity> abs_c, rel_c;
    for (const auto& q : qs) {
      if (q.kind == QKind::kHeading || (q.kind == QKind::kPlain && q.begin > s.trig && !q.number.has_thousand))
        abs_c.push_back(q);
      else if (q.kind == QKind::kAngle)
        rel_c.push_back(q);
      if (q.kind == QKind::kAlt || q.kind == QKind::kSpeed) break;
    }
    std::optional<Quantity> abs = pick(abs_c, s, "heading"), rel = pick(rel_c, s, "heading");
    bool correction = word_in(s.begin, s.end, {"correction", "disregard"});
    int turn = 0;
    if (word_in(s.begin, s.end, {"left"})) turn = -1;
    if (word_in(s.begin, s.end, {"right"}) && find_word(s.begin, s.end, {"right"}) < find_word(s.begin, s.end, {"left"}))
      turn = 1;
    // Named directions: "due south", "north-east", "towards the west".
    double named = -1;
    for (size_t i = s.begin; i < s.end && named < 0; ++i)
      if (word(i, {"north", "south", "east", "west"}))
        named = compass(t_[i].text, i + 1 < s.end ? t_[i + 1].text : "");
    const AircraftView* now = state(ids.front());
    double hdg = -1;
    std::string id = ids.front();
    auto refs = refs_in(s.begin, s.end, RefKind::kAircraft);
    if (abs && (abs->kind == QKind::kHeading || !(rel && rel->begin < abs->begin && !correction))) {
      hdg = abs->value;
      if (!abs->number.typed && abs->number.leading_digit_word && abs->number.groups == 2 && hdg < 40) hdg *= 10.0;
      if (hdg > 360) {
        auto r = repaired(*abs, 0.0, 360.0, 5.0);
        if (!r) return need("What heading should " + id + " fly? I heard " + fmt_int(hdg) + ".");
        hdg = *r;
      }
    } else if (rel && rel->turn == 0 && turn == 0) {
      hdg = rel->value;  // "to one hundred and twenty degrees"
    } else if (rel) {
      if (!now) return need("What is the current heading of " + id + "?");
      int dir = rel->turn != 0 ? rel->turn : turn;
      if (dir == 0) return need("Should " + id + " turn left or right?");
      hdg = now->hdg_deg + dir * rel->value;
    } else if (named >= 0) {
      hdg = named;
    } else if (word_in(s.begin, s.end, {"around", "opposite", "reverse"})) {
      if (!now) return need("What is the current heading of " + id + "?");
      hdg = now->hdg_deg + 180.0;
    } else if (word_in(s.trig >= 2 ? s.trig - 2 : 0, s.end, {"present", "current", "continue"}) && now) {
      hdg = now->hdg_deg;
    } else if (refs.size() >= 2 && word_in(s.begin, s.end, {"same", "match", "as"})) {
      const AircraftView* src = state(refs.back()->name);
      if (!src) return need("What is the heading of " + refs.back()->name + "?");
      id = refs.front()->name;
      hdg = src->hdg_deg;
      ids = {id};
    } else {
      return need("What heading should " + id + " fly?");
    }
    std::string h = fmt(wrap_heading(std::round(hdg * 1000.0) / 1000.0));
    for (auto& a : ids) out_.push_back("HDG " + a + " " + h);
  }

  void vspeed(const Segment& s) {
    auto id = acid(s, "change its vertical speed");
    if (!id) return;
    std::optional<Quantity> v;
    for (const auto& q : quantities(s))
      if (q.kind == QKind::kVs || (q.kind == QKind::kPlain && q.begin > s.trig) ||
          (q.kind == QKind::kAlt && !q.flight_level && q.begin > s.trig)) {
        v = q;
        break;
      }
    if (!v) return need("What vertical speed should " + *id + " fly, in feet per minute?");
    double fpm = v->value;
    if (fpm > 0 && direction(s) < 0) fpm = -fpm;
    out_.push_back("VS " + *id + " " + fmt_int(fpm));
  }

  // ---- create / move ----
  struct Position {
    std::optional<double> lat, lon;
  };
  Position position(const std::vector<Quantity>& qs, size_t trig) const {
    Position p;
    for (const auto& q : qs) {
      if (q.kind == QKind::kLat && !p.lat) p.lat = q.value;
      if (q.kind == QKind::kLon && !p.lon) p.lon = q.value;
    }
    if (p.lat && p.lon) return p;
    // Two bare numbers in a row after "at"/"position"/"to": "at 0 0", "position 51.9, 4.4".
    for (size_t k = 0; k + 1 < qs.size(); ++k) {
      const auto &a = qs[k], &b = qs[k + 1];
      if (a.begin < trig || a.kind != QKind::kPlain || b.kind != QKind::kPlain) continue;
      size_t gap = b.begin - a.end;
      if (gap > 1) continue;
      if (std::fabs(a.value) <= 90 && std::fabs(b.value) <= 180) return {a.value, b.value};
    }
    return p;
  }

  void create(const Segment& s) {
    // Several aircraft in one request: each id followed closely by a type starts one.
    auto acs = refs_in(s.begin, s.end, RefKind::kAircraft);
    std::vector<size_t> starts;
    for (const auto* r : acs) {
      if (r->exists) continue;
      if (!refs_in(r->end, std::min(s.end, r->end + 4), RefKind::kType).empty() || starts.empty())
        starts.push_back(r->begin);
    }
    if (starts.size() <= 1) return create_one(s, s.begin);
    for (size_t k = 0; k < starts.size(); ++k) {
      Segment sub = s;
      sub.begin = k == 0 ? s.begin : starts[k];
      sub.trig = sub.begin;
      sub.end = k + 1 < starts.size() ? starts[k + 1] : s.end;
      create_one(sub, starts[k]);
    }
  }

  void create_one(const Segment& s, size_t id_from) {
    std::string id;
    for (const auto* r : refs_in(id_from, s.end, RefKind::kAircraft))
      if (!r->exists) {
        id = r->name;
        break;
      }
    if (id.empty()) {
      // "named X" / "called X" / "callsign X" / "with id X": take the token as written
      size_t k = find_word(s.begin, s.end, {"named", "called", "callsign", "id"});
      if (k + 1 < s.end && t_[k + 1].kind == TokKind::kWord) id = t_[k + 1].raw;
    }
    std::string type;
    auto types = refs_in(s.begin, s.end, RefKind::kType);
    if (!types.empty()) type = types.front()->name;
    auto refs = refs_in(s.begin, s.end, RefKind::kAircraft);
    const AircraftView* model = nullptr;
    for (const auto* r : refs)
      if (r->exists && word_in(s.begin, s.end, {"same"})) model = state(r->name);
    if (type.empty() && model && word_in(s.begin, s.end, {"type"})) type = model->type;
    auto qs = quantities(s);
    Position p = position(qs, s.trig);
    std::optional<double> hdg, alt, spd, mach;
    bool fl = false;
    for (const auto& q : qs) {
      if (q.kind == QKind::kHeading && !hdg) hdg = q.value;
      if (q.kind == QKind::kAlt && !alt) alt = q.value, fl = q.flight_level;
      if (q.kind == QKind::kSpeed && !spd && !mach) spd = q.value;
      if (q.kind == QKind::kMach && !spd && !mach) mach = q.value;
    }
    if (!hdg) {
      size_t h = find_word(s.begin, s.end, {"heading", "hdg"});
      if (h < s.end && h + 1 < s.end && word(h + 1, {"north", "south", "east", "west"})) {
        double c = compass(t_[h + 1].text, h + 2 < s.end ? t_[h + 2].text : "");
        if (c >= 0) hdg = c;
      }
    }
    if (model && word_in(s.begin, s.end, {"altitude"}) && !alt) {
      alt = units::m_to_ft(model->alt_m);
      fl = true;
    }
    if (model && word_in(s.begin, s.end, {"speed"}) && !spd && !mach) {
      if (model->mach > 0) mach = model->mach;
      else spd = units::ms_to_kt(model->cas_ms);
    }
    std::vector<std::string> missing;
    if (id.empty()) missing.push_back("callsign");
    if (type.empty()) missing.push_back("aircraft type");
    if (!p.lat || !p.lon) missing.push_back("position");
    if (!missing.empty())
      return need("To create the aircraft I need its " + text::join(missing, ", ") + ". What should they be?");
    std::string cmd = "CRE " + id + " " + type + " " + fmt(*p.lat) + " " + fmt(*p.lon);
    if (hdg || alt || spd || mach) cmd += " " + fmt(hdg.value_or(0.0));
    if (alt || spd || mach) cmd += " " + (alt ? fmt_alt(*alt, fl) : std::string("0"));
    if (spd) cmd += " " + fmt_int(*spd);
    if (mach) cmd += " " + fmt_mach(*mach);
    out_.push_back(cmd);
    subject_ = id;
  }

  void move(const Segment& s) {
    auto id = acid(s, "move");
    if (!id) return;
    auto qs = quantities(s);
    Position p = position(qs, s.trig);
    if (!p.lat || !p.lon) return need("Where should " + *id + " go? Please give a latitude and longitude.");
    std::optional<std::string> alt, hdg, spd, vs;
    for (const auto& q : qs) {
      if (q.kind == QKind::kAlt && !alt) alt = fmt_alt(q.value, q.flight_level);
      if (q.kind == QKind::kHeading && !hdg) hdg = fmt(q.value);
      if (q.kind == QKind::kSpeed && !spd) spd = fmt_int(q.value);
      if (q.kind == QKind::kMach && !spd) spd = fmt_mach(q.value);
      if (q.kind == QKind::kVs && !vs) vs = fmt_int(q.value);
    }
    const AircraftView* now = state(*id);
    std::string cmd = "MOVE " + *id + " " + fmt(*p.lat) + " " + fmt(*p.lon);
    std::vector<std::optional<std::string>> opt = {alt, hdg, spd, vs};
    size_t last = 0;
    for (size_t k = 0; k < opt.size(); ++k)
      if (opt[k]) last = k + 1;
    for (size_t k = 0; k < last; ++k) {
      if (opt[k]) {
        cmd += " " + *opt[k];
        continue;
      }
      // a gap before a later value: keep the current state there
      if (!now) return need("Which altitude, heading and speed should " + *id + " have?");
      double cur[] = {units::m_to_ft(now->alt_m), now->hdg_deg, units::ms_to_kt(now->cas_ms), 0.0};
      cmd += " " + fmt_int(cur[k]);
    }
    out_.push_back(cmd);
  }

  void remove(const Segment& s) {
    std::vector<std::string> ids;
    if (word_in(s.begin, s.end, {"all", "both", "every", "everything"})) {
      for (const auto& a : fleet_) ids.push_back(a.id);
      if (ids.empty()) return need("There are no aircraft. Which aircraft should I delete?");
    } else {
      ids = acids(s);
    }
    if (ids.empty()) return need("Which aircraft should I delete? Please give its callsign.");
    for (auto& id : ids) out_.push_back("DEL " + id);
  }

  // ---- route ----
  // A waypoint named in [b, e): a known name, an upper-case name, or a
  // spoken name matched against the world's waypoints.
  std::optional<std::string> waypoint(size_t b, size_t e, const std::string& acid_id) const {
    auto w = refs_in(b, e, RefKind::kWaypoint);
    if (!w.empty()) return w.front()->name;
    if (!world_) return std::nullopt;
    std::vector<std::string> names = world_->waypoints();
    if (const AircraftView* a = state(acid_id))
      for (const auto& r : a->route)
        if (std::find(names.begin(), names.end(), r) == names.end()) names.push_back(r);
    if (names.empty()) return std::nullopt;
    std::optional<Match> best;
    for (size_t i = b; i < e && i < t_.size(); ++i) {
      if (used_[i] || t_[i].kind != TokKind::kWord || is_number_word(t_[i])) continue;
      const std::string& w0 = t_[i].text;
      if (w0.size() < 2 || (is_keyword(w0) && w0 != "direct") || is_filler(w0)) continue;
      std::string cand = w0;
      for (size_t k = 0; k < 2; ++k) {
        auto m = best_match(cand, names);
        if (m && (!best || m->score > best->score)) best = m;
        if (i + k + 1 >= e || t_[i + k + 1].kind != TokKind::kWord) break;
        cand += t_[i + k + 1].text;
      }
    }
    if (best && best->score >= 0.5) return names[best->index];
    return std::nullopt;
  }

  // A name said after "direct (to)" that nothing in the world matches: the
  // word as spoken, or letters spelled with the phonetic alphabet ("november
  // tango mike" -> NTM). Used when there is no world to match against.
  std::optional<std::string> spoken_name(size_t b, size_t e) const {
    if (world_ && !world_->waypoints().empty()) return std::nullopt;
    for (const auto& a : fleet_)
      if (!a.route.empty()) return std::nullopt;
    size_t i = b;
    while (i < e && (word(i, {"to", "the", "ah", "uh", "direct", "via", "now", "point"}) || used_[i])) ++i;
    std::string letters;
    for (size_t k = i; k < e && t_[k].kind == TokKind::kWord && phonetic_letter(t_[k].text) != 0; ++k)
      letters += phonetic_letter(t_[k].text);
    if (letters.size() >= 2) return letters;
    if (i < e && t_[i].kind == TokKind::kWord && is_alpha(t_[i].text) && t_[i].text.size() >= 3 &&
        !is_keyword(t_[i].text) && !is_number_word(t_[i]))
      return text::upper(t_[i].text);
    return std::nullopt;
  }

  std::optional<std::string> single_route_waypoint(const std::string& id) const {
    const AircraftView* a = state(id);
    if (a && a->route.size() == 1) return a->route.front();
    return std::nullopt;
  }

  void direct(const Segment& s) {
    auto id = acid(s, "fly direct");
    if (!id) return;
    auto wp = waypoint(s.trig, s.end, *id);
    if (!wp) wp = single_route_waypoint(*id);
    if (!wp) wp = spoken_name(s.trig + 1, s.end);
    if (!wp) return need("Direct to which waypoint should " + *id + " fly?");
    // DIRECT needs the waypoint in the route: a known aircraft whose route
    // lacks it gets it added first.
    for (const auto& a : fleet_)
      if (text::iequals(a.id, *id) &&
          std::none_of(a.route.begin(), a.route.end(), [&](const std::string& r) { return text::iequals(r, *wp); }))
        out_.push_back("ADDWPT " + *id + " " + *wp);
    out_.push_back("DIRECT " + *id + " " + *wp);
    // a level said in the same breath without its verb ("direct LIVVN ... six thousand")
    for (const auto& q : quantities(s))
      if (q.begin > s.trig && q.kind == QKind::kAlt && q.number.has_thousand)
        if (auto ft = repaired(q, 0.0, 60000.0, 100.0)) return out_.push_back("ALT " + *id + " " + fmt_alt(*ft, false));
  }

  void add_waypoint(const Segment& s) {
    auto id = acid(s, "get the waypoint");
    if (!id) return;
    auto qs = quantities(s);
    Position p = position(qs, s.trig);
    std::string where;
    if (p.lat && p.lon) {
      where = fmt(*p.lat) + " " + fmt(*p.lon);
    } else if (auto wp = waypoint(s.trig, s.end, *id)) {
      where = *wp;
    } else if (word_in(s.trig, s.end, {"it"}) && !last_waypoint_.empty()) {
      where = last_waypoint_;
    } else {
      return need("Where should the waypoint for " + *id + " be? Please give a name or a latitude and longitude.");
    }
    std::string cmd = "ADDWPT " + *id + " " + where;
    std::optional<std::string> alt, spd;
    for (const auto& q : qs) {
      if (q.kind == QKind::kAlt && !alt) alt = fmt_alt(q.value, q.flight_level);
      if (q.kind == QKind::kSpeed && !spd) spd = fmt_int(q.value);
      if (q.kind == QKind::kMach && !spd) spd = fmt_mach(q.value);
    }
    if (alt || spd) cmd += " " + alt.value_or("");
    if (spd) cmd += " " + *spd;
    out_.push_back(cmd);
  }

  void define_waypoint(const Segment& s) {
    std::string name;
    auto w = refs_in(s.begin, s.end, RefKind::kWaypoint);
    if (!w.empty()) name = w.front()->name;
    if (name.empty()) {
      auto a = refs_in(s.begin, s.end, RefKind::kAircraft);  // "EXIT1" reads like an id
      if (!a.empty() && !a.front()->exists) name = text::upper(a.front()->name);
    }
    if (name.empty()) {
      size_t k = find_word(s.begin, s.end, {"named", "called"});
      if (k + 1 < s.end && t_[k + 1].kind == TokKind::kWord) name = text::upper(t_[k + 1].raw);
    }
    Position p = position(quantities(s), s.trig);
    if (name.empty() || !p.lat || !p.lon)
      return need(name.empty() ? "What should the waypoint be called, and where is it?"
                               : "Where is waypoint " + name + "? Please give a latitude and longitude.");
    out_.push_back("DEFWPT " + name + " " + fmt(*p.lat) + " " + fmt(*p.lon));
    last_waypoint_ = name;
  }

  void delete_waypoint(const Segment& s) {
    auto id = acid(s, "lose the waypoint");
    if (!id) return;
    auto wp = waypoint(s.trig, s.end, *id);
    if (!wp) return need("Which waypoint should I remove from the route of " + *id + "?");
    out_.push_back("DELWPT " + *id + " " + *wp);
  }

  void dest_orig(const Segment& s, const char* cmd) {
    auto id = acid(s, "get it");
    if (!id) return;
    Position p = position(quantities(s), s.trig);
    std::string where;
    auto w = refs_in(s.begin, s.end, RefKind::kWaypoint);
    if (!w.empty()) {
      where = w.back()->name;
    } else if (p.lat && p.lon) {
      where = fmt(*p.lat) + " " + fmt(*p.lon);
    } else {
      return need(std::string("Which airport should be the ").append(cmd[0] == 'D' ? "destination" : "origin") +
                  " of " + *id + "? Please give its ICAO code.");
    }
    out_.push_back(std::string(cmd) + " " + *id + " " + where);
  }

  void nav(const Segment& s, const char* cmd) {
    auto id = acid(s, std::string("switch ").append(cmd).c_str());
    if (!id) return;
    int on = on_off(s);
    if (on < 0) on = last_on_ < 0 ? 1 : last_on_;
    last_on_ = on;
    out_.push_back(std::string(cmd) + " " + *id + (on ? " ON" : " OFF"));
  }

  void one_acid(const Segment& s, const char* cmd, const char* what) {
    auto id = acid(s, what);
    if (id) out_.push_back(std::string(cmd) + " " + *id);
  }

  void bank(const Segment& s) {
    auto id = acid(s, "get a bank limit");
    if (!id) return;
    for (const auto& q : quantities(s))
      if (q.kind == QKind::kAngle || q.kind == QKind::kPlain) return out_.push_back("BANK " + *id + " " + fmt(q.value));
    need("What bank angle limit, in degrees, should " + *id + " have?");
  }

  // ---- simulation control ----
  void fast_forward(const Segment& s) {
    for (const auto& q : quantities(s)) {
      if (q.kind == QKind::kTime) return out_.push_back("FF " + fmt(q.value));
      if (q.kind == QKind::kMult) return out_.push_back("DTMULT " + fmt(q.value));  // "speed the sim up 10 times"
    }
    out_.push_back("FF");
  }
  void time_step(const Segment& s) {
    for (const auto& q : quantities(s))
      if (q.kind == QKind::kTime || q.kind == QKind::kPlain) return out_.push_back("DT " + fmt(q.value));
    need("What time step, in seconds, should the simulation use?");
  }
  void time_mult(const Segment& s) {
    for (const auto& q : quantities(s))
      if (q.kind == QKind::kMult || q.kind == QKind::kPlain) return out_.push_back("DTMULT " + fmt(q.value));
    need("How many times real time should the simulation run?");
  }
  void seed(const Segment& s) {
    for (const auto& q : quantities(s))
      if (q.kind == QKind::kPlain) return out_.push_back("SEED " + fmt_int(q.value));
    need("Which random seed should I set?");
  }
  void scenario(const Segment& s) {
    for (size_t i = s.begin; i < s.end; ++i)
      if (t_[i].kind == TokKind::kWord && text::lower(t_[i].raw).find(".scn") != std::string::npos)
        return out_.push_back("IC " + t_[i].raw);
    need("Which scenario file should I load?");
  }
  void echo(const Segment& s) {
    for (size_t i = s.begin; i < s.end; ++i)
      if (t_[i].kind == TokKind::kQuoted) return out_.push_back("ECHO " + t_[i].raw);
    need("What text should I print?");
  }
  void switch_cmd(const Segment& s, const char* cmd) {
    int on = on_off(s);
    if (on < 0) on = last_on_ < 0 ? 1 : last_on_;
    last_on_ = on;
    out_.push_back(std::string(cmd) + (on ? " ON" : " OFF"));
  }
  void resolution(const Segment& s) {
    size_t b = s.begin > 0 ? s.begin - 1 : s.begin;
    int on = on_off(s);
    if (word_in(0, t_.size(), {"mvp"}) || word_in(b, s.end, {"voltage", "potential"})) {
      return out_.push_back("RESO MVP");
    }
    if (on == 0) return out_.push_back("RESO OFF");
    need("Which conflict resolution method should I use (for example MVP), or should it be off?");
  }
  void zone(const Segment& s) {
    auto qs = quantities(s);
    bool vertical = word_in(s.begin, s.end, {"vertical", "height", "zonedh"});
    size_t before = out_.size();
    for (const auto& q : qs) {
      if (q.kind == QKind::kDist || (q.kind == QKind::kPlain && !vertical)) out_.push_back("ZONER " + fmt(q.value));
      if (q.kind == QKind::kAlt || (q.kind == QKind::kPlain && vertical)) out_.push_back("ZONEDH " + fmt(q.value));
    }
    if (out_.size() == before)
      need(vertical ? "What half-height, in feet, should the protected zone have?"
                    : "What radius, in nautical miles, should the protected zone have?");
  }
  void look_ahead(const Segment& s) {
    for (const auto& q : quantities(s))
      if (q.kind == QKind::kTime || q.kind == QKind::kPlain) return out_.push_back("DTLOOK " + fmt(q.value));
    need("How far ahead, in seconds, should conflict detection look?");
  }

  const WorldView* world_;
  std::vector<AircraftView> fleet_;
  std::vector<Token> t_;
  std::vector<bool> used_;
  std::vector<Reference> refs_;
  std::vector<std::string> out_;
  std::string ask_;
  std::string pending_;  // question of a value instruction without a value
  std::string subject_;
  std::string last_waypoint_;
  // The condition a target command leaves for a following "then" (US
  // phraseology: "descend and maintain 4000 then reduce speed to 210"):
  // "ATALT KLM1 4000" or "ATSPD KLM1 210"; empty when none.
  std::string last_cond_;
  int last_on_ = -1;
};

}  // namespace

std::string Translation::text() const { return asked() ? ask : text::join(commands, " ; "); }

Translation translate_offline(std::string_view utterance, const WorldView* world) {
  return Parser(utterance, world).run();
}

}  // namespace squawk::translate
