#include "translate/references.h"

#include <algorithm>
#include <cctype>

#include "core/text.h"
#include "translate/fuzzy.h"
#include "translate/number_words.h"
#include "translate/tables.h"
#include "translate/vocabulary.h"

namespace squawk::translate {
namespace {

// Digits and letters of a spoken callsign, one entry per spoken group.
struct Suffix {
  std::vector<std::string> groups;
  std::vector<size_t> ends;  // token index one past each group
  size_t hesitation =
      0;  // groups before a hesitation between digits ("seven eight er niner": 2), else 0
  std::string joined(size_t k) const {
    std::string s;
    for (size_t i = 0; i < k && i < groups.size(); ++i) s += groups[i];
    return s;
  }
};

bool is_word(const Token& t) { return t.kind == TokKind::kWord; }

// A unit said after its number ("two five zero knots", "one zero degrees").
bool is_unit_word(const std::string& w) {
  static const char* kUnits[] = {"knots",   "knot",    "kts",      "kt",       "feet",
                                 "ft",      "foot",    "degrees",  "degree",   "fpm",
                                 "percent", "miles",   "nautical", "mach",     "seconds",
                                 "second",  "minutes", "minute",   "thousand", "hundred"};
  return std::any_of(std::begin(kUnits), std::end(kUnits), [&](const char* u) { return w == u; });
}

// Reads the digits and letters of a callsign from token j on. `restart`: the
// first word of the airline just said; said again, it starts the callsign over
// ("Delta sixty, Delta six forty six") and ends this one.
// `heard_digits`: a word speech recognition writes for a digit ("for", "to": number_words.cpp's
// heard_digit) is that digit where a digit or a spelled letter follows it ("lufthansa for seven
// one", "swiss eight for kilo"); the caller takes that reading only when it is exactly an
// aircraft's id.
Suffix read_suffix(const std::vector<Token>& t, size_t j, const std::vector<bool>& used,
                   const Tables& names, const std::string& restart = "",
                   bool heard_digits = false) {
  Suffix s;
  while (j < t.size() && !used[j] && s.groups.size() < 8) {
    const Token& k = t[j];
    if (!restart.empty() && is_word(k) && k.text == restart) break;
    if (heard_digits && is_word(k) && k.text != "a" && k.text != "on" && heard_digit(k.text) >= 0 &&
        j + 1 < t.size() && !used[j + 1] && is_word(t[j + 1]) &&
        (digit_word(t[j + 1].text) >= 0 || names.phonetic_letter(t[j + 1].text) != 0)) {
      s.groups.push_back(std::to_string(heard_digit(k.text)));
      s.ends.push_back(++j);
      continue;
    }
    if (k.kind == TokKind::kNumber) {
      // A typed flight number with its letters, lexed as digits and a glued
      // word ("Ryanair 8UK"); a glued unit ("250kt", "30k") is not one.
      if (s.groups.empty() && k.spelled && k.raw.find('.') == std::string::npos && j + 1 < t.size() &&
          t[j + 1].glued && is_word(t[j + 1]) && t[j + 1].raw.size() <= 2 &&
          !names.vocabulary().is_keyword(t[j + 1].text)) {
        s.groups.push_back(k.raw + text::upper(t[j + 1].raw));
        s.ends.push_back(j += 2);
        break;
      }
      if (k.spelled || k.num < 0 || k.num >= 1e6 || k.num != static_cast<long long>(k.num)) break;
      s.groups.push_back(k.raw.find(',') == std::string::npos ? k.raw : std::to_string(static_cast<long long>(k.num)));
      s.ends.push_back(++j);
      continue;
    }
    if (!is_word(k)) break;
    // (a flight number typed as one word, digits, a letter or two and digits: "Cool Red 2Z221",
    // "Cebu 5J561")
    auto typed_number = [](const std::string& w) {
      size_t a = 0, b;
      while (a < w.size() && std::isdigit(static_cast<unsigned char>(w[a]))) ++a;
      for (b = a; b < w.size() && std::isalpha(static_cast<unsigned char>(w[b]));) ++b;
      return a >= 1 && a <= 4 && b > a && b <= a + 2 && w.size() > b && w.size() <= b + 4 &&
             std::all_of(w.begin() + static_cast<long>(b), w.end(),
                         [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    };
    if (s.groups.empty() && typed_number(k.raw)) {
      s.groups.push_back(text::upper(k.raw));
      s.ends.push_back(++j);
      break;
    }
    // One unknown word of four letters or more between spoken digits is
    // recognition noise ("JetBlue eight tier thirteen").
    if (!s.groups.empty() && k.text.size() >= 4 && !is_number_word(k) && j + 1 < t.size() &&
        is_word(t[j + 1]) && is_number_word(t[j + 1]) && j > 0 && is_number_word(t[j - 1]) &&
        !names.vocabulary().is_keyword(k.text) && !names.vocabulary().is_filler(k.text) &&
        names.phonetic_letter(k.text) == 0 && !names.airline_by_telephony(k.text)) {
      ++j;
      continue;
    }
    // a hesitation between spoken digits ("seven eight er niner"), or between the digits and
    // the letters ("two five uh foxtrot"), is skipped, and remembered
    if ((k.text == "ah" || k.text == "uh" || k.text == "um" || k.text == "er") &&
        !s.groups.empty() && s.hesitation == 0 && j + 1 < t.size() && is_word(t[j + 1]) &&
        (digit_word(t[j + 1].text) >= 0 || names.phonetic_letter(t[j + 1].text) != 0)) {
      s.hesitation = s.groups.size();
      ++j;
      continue;
    }
    // "twenty-three oh seven": "oh" between spoken digits is a zero
    if ((k.text == "oh" || k.text == "o") && !s.groups.empty() && j + 1 < t.size() && is_word(t[j + 1]) &&
        digit_word(t[j + 1].text) >= 0) {
      s.groups.emplace_back("0");
      s.ends.push_back(++j);
      continue;
    }
    if (k.text == "hundred" || k.text == "thousand") {
      // "American one hundred", "Lufthansa four hundred", "Aeroflot seventeen hundred": a
      // flight number said as a number, one group of one or two digits (no leading zero) and
      // "hundred" with no number or unit after them
      static const char* kUnits[] = {"feet", "ft", "foot", "knots", "knot", "kts", "kt"};
      const bool value_after =
          j + 1 < t.size() &&
          (is_number_word(t[j + 1]) ||
           std::any_of(std::begin(kUnits), std::end(kUnits),
                       [&](const char* u) { return is_word(t[j + 1]) && t[j + 1].text == u; }));
      if (k.text == "hundred" && s.groups.size() == 1 && s.groups[0].size() <= 2 &&
          s.groups[0][0] != '0' && !value_after) {
        s.groups[0] += "00";
        s.ends[0] = ++j;
        break;
      }
      // "LATAM three six hundred": two spoken digits before "hundred" are the flight number's
      // first two digits (3600)
      const auto digit = [](const std::string& g) {
        return g.size() == 1 && std::isdigit(static_cast<unsigned char>(g[0]));
      };
      if (k.text == "hundred" && s.groups.size() == 2 && digit(s.groups[0]) && digit(s.groups[1]) &&
          s.groups[0][0] != '0' && !value_after) {
        s.groups[0] += s.groups[1] + "00";
        s.groups.pop_back();
        s.ends.pop_back();
        s.ends[0] = ++j;
        break;
      }
      if (!s.groups.empty()) {
        s.groups.pop_back();
        s.ends.pop_back();
      }
      break;
    }
    if (is_number_word(k)) {
      // "eight in eighty two" is how speech recognition writes "eighteen eighty two".
      const int d = digit_word(k.text);
      if (d >= 3 && j + 2 < t.size() && is_word(t[j + 1]) && t[j + 1].text == "in" && is_number_word(t[j + 2])) {
        s.groups.push_back("1" + std::to_string(d));
        s.ends.push_back(j += 2);
        continue;
      }
      // One spoken group: a digit, a teen, or a tens word with its unit digit.
      size_t e = j + 1;
      if (j + 1 < t.size() && digit_word(t[j + 1].text) > 0 && digit_word(k.text) < 0 && k.text.ends_with("ty")) e = j + 2;
      std::vector<Token> group(t.begin() + static_cast<long>(j), t.begin() + static_cast<long>(e));
      auto v = read_number(group, 0);
      if (!v) break;
      s.groups.push_back(v->digits);
      s.ends.push_back(e);
      j = e;
      continue;
    }
    char letter = names.phonetic_letter(k.text);
    if (letter == 0 && k.raw.size() == 1 && std::isupper(static_cast<unsigned char>(k.raw[0])) && k.raw != "A" &&
        k.raw != "I")
      letter = k.raw[0];
    if (letter != 0 && !s.groups.empty()) {
      s.groups.emplace_back(1, letter);
      s.ends.push_back(++j);
      continue;
    }
    break;
  }
  return s;
}

std::vector<std::string> route_and_defined_waypoints(const WorldView* world) {
  std::vector<std::string> names;
  if (!world) return names;
  names = world->waypoints();
  for (const auto& a : world->aircraft())
    for (const auto& w : a.route) names.push_back(w);
  return names;
}

bool in_list(const std::vector<std::string>& names, const std::string& s) {
  return std::any_of(names.begin(), names.end(), [&](const std::string& n) { return text::iequals(n, s); });
}

// Letters at the front of an id ("DLH4AB" -> "DLH") and the rest ("4AB").
std::pair<std::string, std::string> split_id(const std::string& id) {
  size_t i = 0;
  while (i < id.size() && i < 3 && std::isalpha(static_cast<unsigned char>(id[i]))) ++i;
  return {id.substr(0, i), id.substr(i)};
}

struct CallsignMatch {
  std::string id;
  double score = -1.0;
  size_t groups = 0;     // suffix groups used
  double airline = 0.0;  // similarity of the airline part
  double digits = 0.0;   // similarity of the digits and letters
};

// Matches a spoken airline (ICAO prefix if known, else the spoken words) and
// suffix against the world's aircraft.
CallsignMatch match_world(const std::string& icao, const std::string& words, const Suffix& suf,
                          const std::vector<AircraftView>& fleet, const Tables& names) {
  CallsignMatch best;
  for (const auto& a : fleet) {
    auto [prefix, rest] = split_id(a.id);
    double airline = 0.0;
    if (!icao.empty()) {
      airline = text::iequals(icao, prefix) ? 1.0 : 0.0;
    } else if (!words.empty()) {
      airline = similarity(words, prefix);
      for (const auto& tel : names.telephony_of(prefix)) airline = std::max(airline, similarity(words, tel));
    }
    double digits = 0.0;
    size_t groups = suf.groups.size();
    for (size_t k = 1; k <= suf.groups.size(); ++k) {
      double d = plain_similarity(suf.joined(k), rest);
      if (d > digits) {
        digits = d;
        groups = k;
      }
    }
    // Nothing said for the airline: the digits alone decide.
    double score = icao.empty() && words.empty() ? digits : 0.4 * airline + 0.6 * digits;
    if (score > best.score) best = {a.id, score, groups, airline, digits};
  }
  return best;
}

void mark(std::vector<bool>& used, size_t b, size_t e) {
  for (size_t i = b; i < e && i < used.size(); ++i) used[i] = true;
}

// Skips "heavy" / "super" after a callsign.
size_t after_weight(const std::vector<Token>& t, size_t e) {
  while (e < t.size() && is_word(t[e]) && (t[e].text == "heavy" || t[e].text == "super")) ++e;
  return e;
}

}  // namespace


std::vector<Reference> find_references(const std::vector<Token>& t, const WorldView* world, std::vector<bool>& used,
                                       const Tables& names) {
  std::vector<Reference> refs;
  const std::vector<AircraftView> fleet = world ? world->aircraft() : std::vector<AircraftView>{};
  const std::vector<std::string> wpts = route_and_defined_waypoints(world);
  auto world_id = [&](const std::string& s) -> const AircraftView* {
    for (const auto& a : fleet)
      if (text::iequals(a.id, s)) return &a;
    return nullptr;
  };
  Heard heard;  // how the callsign being added was heard, when matched inexactly
  auto add = [&](RefKind kind, std::string name, size_t b, size_t e, bool exists, bool spoken) {
    mark(used, b, e);
    refs.push_back({kind, std::move(name), b, e, exists, spoken, heard});
    heard = Heard{};
  };

  // Typed aircraft ids and aircraft types.
  for (size_t i = 0; i < t.size(); ++i) {
    // a family said as its number after an article ("a 737", "an 320"): that type
    if (!used[i] && t[i].kind == TokKind::kNumber && t[i].raw.size() == 3 && i > 0 &&
        (t[i - 1].text == "a" || t[i - 1].text == "an")) {
      if (auto ty = names.aircraft_type("", t[i].raw)) {
        add(RefKind::kType, *ty, i, i + 1, false, false);
        continue;
      }
    }
    // a route or defined waypoint named by digits and letters after them ("5450N", a scenario's NAT
    // point), which the lexer splits into a number and a word glued to it
    if (!used[i] && t[i].kind == TokKind::kNumber && i + 1 < t.size() && !used[i + 1] &&
        t[i + 1].glued && is_word(t[i + 1]) && in_list(wpts, t[i].raw + t[i + 1].raw)) {
      add(RefKind::kWaypoint, text::upper(t[i].raw + t[i + 1].raw), i, i + 2, true, false);
      continue;
    }
    if (used[i] || !is_word(t[i])) continue;
    const std::string& raw = t[i].raw;
    if (const AircraftView* a = world_id(raw)) {
      add(RefKind::kAircraft, a->id, i, i + 1, true, false);
      continue;
    }
    // a typed callsign split after its airline ("ezy 451"): only an aircraft's exact id
    if (i + 1 < t.size() && t[i + 1].kind == TokKind::kNumber && !used[i + 1] && raw.size() == 3 && is_alpha(raw)) {
      if (const AircraftView* a = world_id(raw + t[i + 1].raw)) {
        add(RefKind::kAircraft, a->id, i, i + 2, true, false);
        continue;
      }
    }
    // a waypoint named like a letter of the phonetic alphabet, said after digits or
    // letters, spells a callsign ("november one two three alpha bravo")
    const bool spelling = names.phonetic_letter(t[i].text) != 0 && i > 0 &&
                          (t[i - 1].kind == TokKind::kNumber || is_number_word(t[i - 1]) ||
                           names.phonetic_letter(t[i - 1].text) != 0);
    if (in_list(wpts, raw) && !spelling) {
      add(RefKind::kWaypoint, text::upper(raw), i, i + 1, true, false);
      continue;
    }
    // a route or defined waypoint whose letters are said apart from its digits ("PKT zero four",
    // "PKT 04"): that waypoint, when the letters and every digit said after them join to its name
    if (is_alpha(raw) && !wpts.empty()) {
      std::string digits;
      size_t e = i + 1;
      if (e < t.size() && !used[e] && t[e].kind == TokKind::kNumber && t[e].raw.size() <= 3 &&
          std::all_of(t[e].raw.begin(), t[e].raw.end(),
                      [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
        digits = t[e++].raw;
      } else {
        for (; e < t.size() && !used[e] && digits.size() < 3 && digit_word(t[e].text) >= 0; ++e)
          digits += static_cast<char>('0' + digit_word(t[e].text));
      }
      const bool more =
          e < t.size() && (t[e].kind == TokKind::kNumber || digit_word(t[e].text) >= 0);
      if (!digits.empty() && !more && in_list(wpts, raw + digits)) {
        add(RefKind::kWaypoint, text::upper(raw + digits), i, e, true, false);
        continue;
      }
    }
    if (names.is_manufacturer(t[i].text) && i + 1 < t.size()) {
      if (auto ty = names.aircraft_type(t[i].text, t[i + 1].raw)) {
        add(RefKind::kType, *ty, i, i + 2, false, false);
        continue;
      }
    }
    // an ICAO designator of letters only, typed in capitals ("EUFI", "GLEX", "CONC"), after "type"
    // or straight after a typed callsign no aircraft has ("create GAF30 EUFI at ..."): that type
    // (elsewhere a place's letters)
    const bool new_id_before = i > 0 && is_word(t[i - 1]) && has_digit(t[i - 1].raw) &&
                               std::isalpha(static_cast<unsigned char>(t[i - 1].raw[0])) &&
                               !world_id(t[i - 1].raw);
    if ((new_id_before || (i > 0 && t[i - 1].text == "type")) && is_alpha(raw) &&
        raw == text::upper(raw)) {
      if (auto ty = names.aircraft_type("", raw); ty && *ty == raw) {
        add(RefKind::kType, *ty, i, i + 1, false, false);
        continue;
      }
    }
    if (i > 0 && t[i - 1].text == "type" && has_digit(raw)) {
      add(RefKind::kType, names.aircraft_type("", raw).value_or(text::upper(raw)), i, i + 1, false, false);
      continue;
    }
    if (has_digit(raw)) {
      if (auto ty = names.aircraft_type("", raw)) {
        add(RefKind::kType, *ty, i, i + 1, false, false);
        continue;
      }
      bool id_like = std::isalpha(static_cast<unsigned char>(raw[0])) && raw.size() >= 2 && raw.size() <= 10 &&
                     std::all_of(raw.begin(), raw.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)); });
      if (id_like) add(RefKind::kAircraft, raw, i, i + 1, false, false);
    }
  }
  // The spoken callsign `id` as it exists in the world: the aircraft of that
  // id, else the best match by sound and digits, whose matched digits then end
  // the reference at `end`. False when nothing in the world fits.
  auto resolve = [&](std::string& id, const std::string& icao, const std::string& spoken, const Suffix& suf,
                     size_t& end) {
    if (const AircraftView* a = world_id(id)) {
      // said with a hesitation between its digits, and the digits before it are another
      // aircraft's ("speedbird seven eight er niner" with BAW78 and BAW789 flying): asked
      const std::string all = suf.joined(suf.groups.size());
      const std::string before = id.substr(0, id.size() - all.size()) + suf.joined(suf.hesitation);
      if (suf.hesitation > 0 && world_id(before))
        heard = {before + " " + t[suf.ends[suf.hesitation - 1]].text + " " +
                     all.substr(suf.joined(suf.hesitation).size()),
                 1.0, 0.0};
      id = a->id;
      return true;
    }
    // a digit that speech recognition wrote as a word after the callsign's digits
    // ("KLM one two three for descend") is that digit when the callsign with it is an aircraft's;
    // "to" or "too" before a word is the infinitive's ("ask Air France one one four to climb")
    if (const size_t e = suf.ends.back();
        e < t.size() && is_word(t[e]) && heard_digit(t[e].text) >= 0 &&
        !((t[e].text == "to" || t[e].text == "too") && e + 1 < t.size() && is_word(t[e + 1]))) {
      if (const AircraftView* a = world_id(id + std::to_string(heard_digit(t[e].text)))) {
        id = a->id;
        end = e + 1;
        return true;
      }
    }
    if (fleet.empty()) return false;
    CallsignMatch m = match_world(icao, spoken, suf, fleet, names);
    if ((m.score < 0.45 && fleet.size() != 1) || m.groups == 0) return false;
    // heard as far as the match read it and the spelled letters after it: digit
    // groups after the match belong to the instruction ("... nine three four two, ten")
    // unless they are one or two digits said singly with an instruction word after them
    // ("Lufthansa four zero four climb" is DLH404 heard, not DLH40 and a stray four): a
    // value is said in three digits or more, or comes after its instruction word or
    // before its unit, never as a digit or two bare before the word (punctuation between
    // them too: "Wizz Air three zero five two, correction, ...", "... five two... correction")
    const std::string said_prefix = id.substr(0, id.size() - suf.joined(suf.groups.size()).size());
    size_t said = m.groups;
    const bool single_digits =
        suf.groups.size() - m.groups <= 2 &&
        std::all_of(suf.groups.begin() + static_cast<long>(m.groups), suf.groups.end(),
                    [](const std::string& g) {
                      return g.size() == 1 && std::isdigit(static_cast<unsigned char>(g[0]));
                    });
    size_t e = suf.ends.back();
    while (e < t.size() && t[e].kind == TokKind::kPunct) ++e;
    if (single_digits && e < t.size() && is_word(t[e]) &&
        names.vocabulary().is_keyword(t[e].text) && !is_unit_word(t[e].text))
      said = suf.groups.size();
    const size_t matched = said;  // groups the reference spans: the digits said singly too
    while (said < suf.groups.size() && !std::isdigit(static_cast<unsigned char>(suf.groups[said][0]))) ++said;
    heard = {said_prefix + text::upper(suf.joined(said)), m.airline, m.digits};
    id = m.id;
    end = suf.ends[std::max(matched, m.groups) - 1];
    return true;
  };
  // Telephony designator + digits/letters.
  auto single_letter = [&](size_t k) {
    return k < t.size() && !used[k] && is_word(t[k]) && t[k].text.size() == 1 && std::isalpha(static_cast<unsigned char>(t[k].text[0]));
  };
  for (size_t i = 0; i < t.size(); ++i) {
    if (used[i] || !is_word(t[i])) continue;
    // A designator spelled out letter by letter: "k l m two six four".
    size_t letters = 0;
    while (letters < 3 && single_letter(i + letters)) ++letters;
    if (letters >= 2) {
      std::string prefix;
      for (size_t k = i; k < i + letters; ++k) prefix += t[k].text;
      Suffix suf = read_suffix(t, i + letters, used, names);
      if (!suf.groups.empty() && std::isdigit(static_cast<unsigned char>(suf.groups[0][0]))) {
        std::string id = text::upper(prefix) + text::upper(suf.joined(suf.groups.size()));
        size_t end = suf.ends.back();
        const bool exists = resolve(id, "", prefix, suf, end);
        add(RefKind::kAircraft, id, i, after_weight(t, end), exists, true);
        i = end - 1;
        continue;
      }
    }
    for (size_t len = std::min(names.max_telephony_words(), t.size() - i); len >= 1; --len) {
      std::string phrase, joined;
      bool ok = true;
      for (size_t k = i; k < i + len; ++k) {
        ok = ok && !used[k] && is_word(t[k]);
        if (k > i) phrase += ' ';
        phrase += t[k].text;
        joined += t[k].text;
      }
      if (!ok) continue;
      // a designator split by speech recognition ("speed bird", "ryan air") is that designator
      auto icao = names.airline_by_telephony(phrase);
      if (!icao && len > 1) icao = names.airline_by_telephony(joined);
      // a telephony said with "Airways" or "Airlines" after it is that airline ("Kenya Airways
      // 212")
      if (!icao && len > 1 &&
          (t[i + len - 1].text == "airways" || t[i + len - 1].text == "airlines"))
        icao = names.airline_by_telephony(std::string_view(phrase).substr(0, phrase.rfind(' ')));
      if (!icao) continue;
      Suffix suf = read_suffix(t, i + len, used, names, t[i].text);
      if (!world_id(*icao + text::upper(suf.joined(suf.groups.size())))) {
        Suffix heard_suf = read_suffix(t, i + len, used, names, t[i].text, true);
        if (world_id(*icao + text::upper(heard_suf.joined(heard_suf.groups.size()))))
          suf = heard_suf;
      }
      if (suf.groups.empty() || names.phonetic_letter(t[i + len].text) != 0) break;
      std::string id = *icao + text::upper(suf.joined(suf.groups.size()));
      // "when you reach 15000", "once it reaches FL200": a telephony that is also a verb of
      // reaching (Reach, RCH), said after its subject or "when"/"once", is the verb unless it names
      // a flying aircraft
      if (len == 1 && i > 0 && (t[i].text == "reach" || t[i].text == "reaches") &&
          in_list({"you", "it", "he", "she", "they", "we", "when", "once", "to"}, t[i - 1].text) &&
          !world_id(id))
        break;
      size_t end = suf.ends.back();
      const bool exists = resolve(id, *icao, phrase, suf, end);
      add(RefKind::kAircraft, id, i, after_weight(t, end), exists, true);
      i = end - 1;
      break;
    }
  }
  // A US registration said after its aircraft's type or maker instead of "November" ("remove
  // Cherokee eight two zero seven kilo", FAA phraseology): one word squawk reads as nothing else,
  // then digits and letters that with "N" before them are exactly an aircraft's id.
  for (size_t i = 0; i + 1 < t.size(); ++i) {
    if (used[i] || !is_word(t[i]) || is_number_word(t[i]) ||
        names.phonetic_letter(t[i].text) != 0 || names.vocabulary().is_keyword(t[i].text) ||
        names.vocabulary().is_filler(t[i].text))
      continue;
    Suffix suf = read_suffix(t, i + 1, used, names);
    if (suf.groups.size() < 2 || !std::isdigit(static_cast<unsigned char>(suf.groups.front()[0])) ||
        !std::isalpha(static_cast<unsigned char>(suf.groups.back()[0])))
      continue;
    if (const AircraftView* a = world_id("N" + text::upper(suf.joined(suf.groups.size())))) {
      add(RefKind::kAircraft, a->id, i, after_weight(t, suf.ends.back()), true, true);
      i = suf.ends.back() - 1;
    }
  }
  // A registration spelled in the phonetic alphabet at the opening ("delta
  // mike echo climb ..."): three letters or more.
  {
    size_t i = 0;
    while (i < t.size() && is_word(t[i]) && names.vocabulary().is_filler(t[i].text) && !used[i]) ++i;
    size_t b = i;
    std::string letters;
    while (i < t.size() && is_word(t[i]) && !used[i] && names.phonetic_letter(t[i].text) != 0) letters += names.phonetic_letter(t[i++].text);
    if (letters.size() >= 3) {
      const AircraftView* known = world_id(letters);
      std::string id = known ? known->id : letters;
      bool exists = known != nullptr;
      if (!exists && !fleet.empty()) {
        auto m = best_match(letters, [&] {
          std::vector<std::string> ids;
          for (const auto& a : fleet) ids.push_back(a.id);
          return ids;
        }());
        if (m && (m->score >= 0.6 || fleet.size() == 1)) {
          heard = {letters, 0.0,
                   m->score};  // letters that spell no aircraft: confirmed, never substituted
          id = fleet[m->index].id;
          exists = true;
        }
      }
      add(RefKind::kAircraft, id, b, after_weight(t, i), exists, true);
    }
  }
  // An opening callsign the table does not know (garbled by speech recognition).
  bool opened = std::any_of(refs.begin(), refs.end(),
                            [](const Reference& r) { return r.kind == RefKind::kAircraft && r.begin <= 2; });
  if (!fleet.empty() && !opened) {
    size_t i = 0;
    while (i < t.size() && is_word(t[i]) && names.vocabulary().is_filler(t[i].text) && !used[i]) ++i;
    size_t words_begin = i;
    std::string words;
    bool keyword = false;  // an instruction word may be a misheard airline name ("front turn" = Frontier)
    bool only_keywords = true;
    // an instruction word after "the", "a" or "an", or "at" among them: no airline's name reads so
    // ("set the wind at 50 8"; "descend the 1723" may still be a flight number)
    bool article = false, article_before = false;
    std::string last_word;  // as typed: two capitals are an airline code ("AC 851")
    while (i < t.size() && i - words_begin < 4 && is_word(t[i]) && !used[i] && !is_number_word(t[i]) &&
           names.phonetic_letter(t[i].text) == 0) {
      keyword = keyword || names.vocabulary().is_keyword(t[i].text);
      // ("climb to FL300, Finnair 7": "to" after an instruction word keeps the words an
      // instruction)
      only_keywords = only_keywords && (names.vocabulary().is_keyword(t[i].text) ||
                                        (i > words_begin && t[i].text == "to"));
      article = article || t[i].text == "at" ||
                (article_before && names.vocabulary().is_keyword(t[i].text));
      article_before =
          article_before || t[i].text == "the" || t[i].text == "a" || t[i].text == "an";
      words += t[i].text;
      last_word = t[i].raw;
      ++i;
    }
    // Letters of the phonetic alphabet between the airline and the digits are
    // part of the garbled airline ("Land Juliett six ninety three").
    size_t letters_end = i;
    while (letters_end < t.size() && letters_end - words_begin < 4 && is_word(t[letters_end]) && !used[letters_end] &&
           names.phonetic_letter(t[letters_end].text) != 0)
      ++letters_end;
    if (letters_end > i && i > words_begin && read_suffix(t, i, used, names).groups.empty()) {
      for (; i < letters_end; ++i) words += t[i].text;
    }
    while (i < t.size() && t[i].kind == TokKind::kPunct && t[i].text == ",") ++i;
    Suffix suf = read_suffix(t, i, used, names);
    // Digits followed by a unit are a quantity ("fast forward 2 minutes", "the protected zone 3
    // miles"), not a callsign.
    auto unit_after = [&](size_t e) {
      static const char* kUnits[] = {
          "s",    "sec",   "secs", "second", "seconds", "min", "mins", "minute", "minutes", "h",
          "hour", "hours", "x",    "times",  "percent", "%",   "nm",   "mile",   "miles"};
      return e < t.size() && is_word(t[e]) &&
             std::any_of(std::begin(kUnits), std::end(kUnits), [&](const char* u) { return t[e].text == u; });
    };
    // Digits with an "x" typed onto them ("go 2x", "run it 4x") are a rate, not a callsign's
    // digits and letter.
    const bool rate = !suf.groups.empty() && suf.ends.front() > 0 &&
                      is_word(t[suf.ends.front() - 1]) && t[suf.ends.front() - 1].glued &&
                      t[suf.ends.front() - 1].text == "x";
    // Instruction words alone before the digits are that instruction and its value ("seed 1234
    // please", "random seed 42"), no airline misheard (that takes a word of its own: "front turn" =
    // Frontier).
    // ("set the wind at 50 8 FL100 ...": an instruction's words with an article or "at" between are
    // no airline)
    const bool instruction_alone = keyword && (only_keywords || article) && i > words_begin;
    if (!suf.groups.empty() && !unit_after(suf.ends.back()) && !instruction_alone && !rate) {
      CallsignMatch m = match_world("", words, suf, fleet, names);
      // With one aircraft, an opening callsign that sounds like nothing else is that aircraft.
      double need = keyword ? 0.55 : fleet.size() == 1 ? 0.0 : 0.5;
      if (m.score >= need && m.groups > 0) {
        // Heard inexactly (asked about) unless every digit and letter said is the aircraft's
        // and either the words are its airline's or no other aircraft has that number (speech
        // recognition garbles airline names far more than digits). Two capitals before the
        // digits ("AC 851", "BA 123") are an airline code squawk has no table for: a partial
        // callsign.
        const std::string said = text::upper(suf.joined(m.groups));
        const bool number_unique = std::count_if(fleet.begin(), fleet.end(), [&](const AircraftView& a) {
                                     return text::iequals(split_id(a.id).second, said);
                                   }) == 1;
        const auto [prefix, number] = split_id(m.id);
        const bool code = last_word.size() == 2 && text::upper(last_word) == last_word &&
                          is_alpha(last_word) && last_word != prefix;
        // (digits said beyond the match, "Garuda four one two" matched to QFA41: inexact too)
        const bool more_said = static_cast<size_t>(m.groups) < suf.groups.size();
        if (said != text::upper(number) || code || more_said || (m.airline < 1.0 && !number_unique))
          heard = {text::upper(words) + text::upper(suf.joined(suf.groups.size())), m.airline,
                   m.digits};
        add(RefKind::kAircraft, m.id, words_begin, after_weight(t, suf.ends[m.groups - 1]), true, true);
      }
    }
  }
  // Waypoint and airport names: upper-case words that are nothing else.
  for (size_t i = 0; i < t.size(); ++i) {
    if (used[i] || !is_word(t[i])) continue;
    const std::string& raw = t[i].raw;
    bool upper = raw.size() >= 3 && raw.size() <= 6 &&
                 std::all_of(raw.begin(), raw.end(), [](char c) { return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)); }) &&
                 std::isalpha(static_cast<unsigned char>(raw[0]));
    static const char* kNotNames[] = {"LNAV", "VNAV", "MVP", "ADS", "NM", "FL", "ASAS", "PZ", "KLM", "VS", "HDG",
                                      "ALT", "SPD", "CRE", "DEL", "ATC", "OFF", "ON", "ILS", "RNAV", "TCAS", "UTC", "GPS"};
    bool reserved = std::any_of(std::begin(kNotNames), std::end(kNotNames), [&](const char* n) { return raw == n; });
    // (a grammar keyword in capitals, "RPZ", "CLIMB", is that word, no name)
    if (upper && !reserved && !names.airline_by_telephony(t[i].text) &&
        !names.vocabulary().is_keyword(t[i].text))
      add(RefKind::kWaypoint, raw, i, i + 1, false, false);
  }
  std::sort(refs.begin(), refs.end(), [](const Reference& a, const Reference& b) { return a.begin < b.begin; });
  return refs;
}

}  // namespace squawk::translate
