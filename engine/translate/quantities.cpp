#include "translate/quantities.h"

#include <cmath>

namespace squawk::translate {
namespace {

bool word_at(const std::vector<Token>& t, size_t i, std::initializer_list<const char*> words) {
  if (i >= t.size() || t[i].kind != TokKind::kWord) return false;
  for (const char* w : words)
    if (t[i].text == w) return true;
  return false;
}

// +1 / -1 for a hemisphere word, 0 otherwise; `lat` tells which axis.
int hemisphere(const std::vector<Token>& t, size_t i, bool& lat) {
  if (word_at(t, i, {"n", "north"})) return lat = true, 1;
  // A lone "s" is south only when a longitude with its hemisphere follows
  // ("33.95 S 151.18 E"); else it is seconds.
  size_t k = i + 1;
  if (k < t.size() && t[k].kind == TokKind::kPunct) ++k;
  bool lon_follows = k + 1 < t.size() && t[k].kind == TokKind::kNumber &&
                     word_at(t, k + 1, {"e", "east", "w", "west"});
  if (word_at(t, i, {"south"}) || (word_at(t, i, {"s"}) && lon_follows)) return lat = true, -1;
  if (word_at(t, i, {"e", "east"})) return lat = false, 1;
  if (word_at(t, i, {"w", "west"})) return lat = false, -1;
  return 0;
}

// Typed degrees and minutes (and seconds) run together, as on charts:
// "5230N" = 52 deg 30 min, "00445E" = 4 deg 45 min, "523015N". Read when
// the digits have that exact length and the plain reading is out of range
// or starts with a zero; else the value as read.
double chart_degrees(const Token& tok, bool lat, double value) {
  const std::string& d = tok.raw;
  const size_t deg = lat ? 2 : 3;
  if (tok.kind != TokKind::kNumber || (d.size() != deg + 2 && d.size() != deg + 4)) return value;
  for (char c : d)
    if (c < '0' || c > '9') return value;
  if (std::fabs(value) <= (lat ? 90.0 : 180.0) && d[0] != '0') return value;
  const int mins = std::stoi(d.substr(deg, 2));
  const int secs = d.size() > deg + 2 ? std::stoi(d.substr(deg + 2, 2)) : 0;
  if (mins >= 60 || secs >= 60) return value;
  return std::stoi(d.substr(0, deg)) + mins / 60.0 + secs / 3600.0;
}

// Degrees and minutes said as groups, as controllers read a chart position: "fifty three thirty
// north" = 53 deg 30 min, "five forty five west" = 5 deg 45 min. Read only when the groups run
// together beyond the axis's range and their last two digits are minutes (under 60) after degrees
// within it; else the value as read.
double spoken_degrees(const SpokenNumber& n, bool lat, double value) {
  const double range = lat ? 90.0 : 180.0;
  const std::string& d = n.digits;
  if (n.typed || n.groups < 2 || n.has_decimal || n.has_hundred || n.has_thousand ||
      std::fabs(value) <= range || d.size() < 3 || d.size() > (lat ? 4u : 5u))
    return value;
  for (char c : d)
    if (c < '0' || c > '9') return value;
  const int mins = std::stoi(d.substr(d.size() - 2));
  const int degs = std::stoi(d.substr(0, d.size() - 2));
  if (mins >= 60 || degs > range) return value;
  return degs + mins / 60.0;
}

void set_position(Quantity& q, bool lat, int sign, const std::vector<Token>& t) {
  q.kind = lat ? QKind::kLat : QKind::kLon;
  if (q.number.typed && q.number.begin < t.size()) q.value = chart_degrees(t[q.number.begin], lat, q.value);
  q.value = spoken_degrees(q.number, lat, q.value);
  q.value = sign * std::fabs(q.value);
}

}  // namespace

std::vector<Quantity> extract_quantities(const std::vector<Token>& t, size_t begin, size_t end,
                                         const std::vector<bool>& skip) {
  std::vector<Quantity> out;
  size_t i = begin;
  size_t floor = begin;  // tokens before it belong to an earlier quantity
  while (i < end && i < t.size()) {
    if (skip[i]) {
      ++i;
      continue;
    }
    // "half a second", "half speed", "double speed", "triple speed"
    if (word_at(t, i, {"half", "double", "triple", "quadruple"})) {
      Quantity q;
      q.begin = i;
      q.value = t[i].text == "half"     ? 0.5
                : t[i].text == "double" ? 2.0
                : t[i].text == "triple" ? 3.0
                                        : 4.0;
      size_t j = i + 1;
      if (word_at(t, j, {"a", "an"})) ++j;
      if (q.value == 0.5 && word_at(t, j, {"second", "seconds", "sec"})) {
        q.kind = QKind::kTime;
        q.end = j + 1;
        out.push_back(q);
        i = j + 1;
        continue;
      }
      if (word_at(t, j, {"speed"})) {
        q.kind = QKind::kMult;
        q.end = j + 1;
        out.push_back(q);
        i = j + 1;
        continue;
      }
      ++i;
      continue;
    }
    auto n = read_number(t, i);
    if (!n || n->end > end) {
      ++i;
      continue;
    }
    Quantity q;
    q.number = *n;
    q.value = n->value;
    q.begin = i;
    size_t j = n->end;
    size_t p = i;  // walks back over prefix words
    auto prev = [&](std::initializer_list<const char*> w) { return p > floor && word_at(t, p - 1, w); };
    bool lat = false;
    // A flight level or a heading said digit by digit is three digits; what follows
    // is another value ("flight level three one zero one thousand five hundred feet
    // per minute", "heading zero four five one one thousand": an altitude, so
    // `thousand` is required after a heading's three digits).
    auto three_digits = [&](size_t min_digits, bool thousand) {
      if (n->typed || !(n->has_thousand || (!thousand && n->digits.size() > 3))) return;
      size_t k = i;
      while (k < end && k < i + 3 && t[k].kind == TokKind::kWord && digit_word(t[k].text) >= 0) ++k;
      if (k < i + min_digits) return;
      std::vector<Token> three(t.begin() + static_cast<long>(i), t.begin() + static_cast<long>(k));
      if (auto v = read_number(three, 0)) {
        q.number = *v;
        q.value = v->value;
        j = k;
      }
    };
    // "when level one zero thousand", "descend level five thousand": "level" alone (no "flight" or
    // "FL") before one or two digit words and "thousand" is an altitude in feet, no flight level.
    auto thousands_after_level = [&] {
      if (n->typed || !n->has_thousand || !prev({"level"}) ||
          (p > floor + 1 && word_at(t, p - 2, {"flight"})))
        return false;
      size_t k = i;
      while (k < end && t[k].kind == TokKind::kWord && digit_word(t[k].text) >= 0) ++k;
      return k > i && k < i + 3 && word_at(t, k, {"thousand"});
    };
    if (thousands_after_level()) {
      q.kind = QKind::kAlt;
      --p;
    } else if (prev({"fl"}) || prev({"level"})) {
      q.kind = QKind::kAlt;
      q.flight_level = true;
      three_digits(1, false);
      if (q.value < 1000.0) q.value *= 100.0;
      --p;
      if (prev({"flight"})) --p;
    } else if (prev({"mach", "m"}) ||
               (prev({"mark"}) && n->has_decimal && n->value < 1.0) ||  // "mark point seven" = Mach
               (prev({"number"}) && p > floor + 1 &&
                word_at(t, p - 2, {"mach"}))) {  // "Mach number 0.78"
      q.kind = QKind::kMach;
      if (q.value >= 1.0 && !n->has_decimal) q.value /= 100.0;
      if (prev({"number"})) --p;
      --p;
    } else if (prev({"heading", "hdg", "headings"})) {
      q.kind = QKind::kHeading;
      three_digits(3, true);
    } else if (prev({"latitude", "lat"})) {
      q.kind = QKind::kLat;
    } else if (prev({"longitude", "lon", "long"})) {
      q.kind = QKind::kLon;
    } else if (p > floor && t[i].kind == TokKind::kNumber && t[i].glued &&
               hemisphere(t, p - 1, lat) != 0 && t[p - 1].text.size() == 1) {
      set_position(q, lat, hemisphere(t, p - 1, lat), t);
      --p;
    }
    if (q.kind == QKind::kPlain || q.kind == QKind::kAlt || q.kind == QKind::kMach) {
      if (word_at(t, j, {"ft", "feet", "foot"})) {
        ++j;
        // "feet a minute", "feet each minute", "feet the minute", "feet in the minute" (French "par
        // minute", Spanish "en el minuto")
        const size_t in = word_at(t, j, {"in"}) && word_at(t, j + 1, {"the"}) ? 1 : 0;
        if (word_at(t, j + in, {"per", "a", "for", "each", "every", "the"}) &&
            word_at(t, j + in + 1, {"minute", "min", "mn"})) {
          q.kind = QKind::kVs;
          j += 2 + in;
        } else if (q.kind != QKind::kAlt) {
          q.kind = QKind::kAlt;
        }
      } else if (word_at(t, j, {"fpm"})) {
        q.kind = QKind::kVs;
        ++j;
      } else if (q.kind == QKind::kPlain && !n->has_decimal && std::fabs(q.value) >= 100.0 &&
                 std::fabs(q.value) < 10000.0 && word_at(t, j, {"per", "a"}) &&
                 word_at(t, j + 1, {"minute", "min"})) {
        // "2000 a minute", "1500 per minute": a climb or descent rate [ft/min] said without its
        // feet
        q.kind = QKind::kVs;
        j += 2;
      } else if (word_at(t, j, {"k"})) {
        q.kind = QKind::kAlt;
        q.value *= 1000.0;
        ++j;
        if (word_at(t, j, {"ft", "feet"})) ++j;
      } else if (word_at(t, j, {"m", "metres", "meters", "metre", "meter"}) &&
                 word_at(t, j + 1, {"per", "a"}) && word_at(t, j + 2, {"s", "second", "sec"}) &&
                 q.kind == QKind::kPlain) {
        // "10 metres per second", "m/s" -> [ft/min], whole; from 40 m/s (7874 ft/min, beyond any
        // climb) an airspeed -> [kt], to 0.1 ("velocity 150 m/s")
        if (std::fabs(q.value) >= 40.0) {
          q.kind = QKind::kSpeed;
          q.value = std::round(q.value * 3600.0 / 1852.0 * 10.0) / 10.0;
        } else {
          q.kind = QKind::kVs;
          q.value = std::round(q.value / 0.3048 * 60.0);
        }
        j += 3;
      } else if (word_at(t, j, {"m", "metres", "meters", "metre", "meter"}) &&
                 q.kind == QKind::kPlain) {
        q.kind = QKind::kAlt;
        q.value = std::round(q.value / 0.3048);  // [ft], whole
        ++j;
      } else if (word_at(t, j, {"kt", "kts", "knots", "knot", "kias", "kn", "kts."})) {
        q.kind = QKind::kSpeed;
        ++j;
      } else if (word_at(t, j, {"mach"}) && q.kind != QKind::kAlt) {  // ("FL320 M.78": two values)
        q.kind = QKind::kMach;
        ++j;
      } else if (word_at(t, j, {"degrees", "degree", "deg", "\xC2\xB0"})) {
        ++j;
        Quantity dms = q;
        bool minutes_lat = lat;
        if (j < end && t[j].kind == TokKind::kNumber && word_at(t, j + 1, {"minutes", "min", "minute"})) {
          dms.value = q.value + t[j].num / 60.0;
          j += 2;
        } else if (j < end && t[j].kind == TokKind::kNumber && t[j].num >= 0 && t[j].num < 60 &&
                   hemisphere(t, j + 1, minutes_lat) != 0) {
          dms.value =
              q.value + t[j].num / 60.0;  // "55 degrees 30 north": minutes without their word
          j += 1;
        }
        int h = hemisphere(t, j, lat);
        if (h != 0) {
          q = dms;
          set_position(q, lat, h, t);
          ++j;
        } else if (word_at(t, j, {"left", "right"})) {
          q.kind = QKind::kAngle;
          q.turn = t[j].text == "left" ? -1 : 1;
          ++j;
        } else if (word_at(t, j, {"to"}) && word_at(t, j + 1, {"the"}) && word_at(t, j + 2, {"left", "right"})) {
          q.kind = QKind::kAngle;
          q.turn = t[j + 2].text == "left" ? -1 : 1;
          j += 3;
        } else {
          q.kind = QKind::kAngle;
        }
      } else if (hemisphere(t, j, lat) != 0) {
        set_position(q, lat, hemisphere(t, j, lat), t);
        ++j;
      } else if (word_at(t, j, {"nm", "miles", "mile", "nautical", "dme"})) {
        q.kind = QKind::kDist;  // [NM] ("20 DME": nautical miles off a DME)
        ++j;
        if (word_at(t, j, {"mile", "miles"})) ++j;
      } else if (word_at(t, j, {"kph", "kmh"}) ||
                 (word_at(t, j, {"km", "kilometres", "kilometers", "kilometre", "kilometer"}) &&
                  word_at(t, j + 1, {"per"}) && word_at(t, j + 2, {"h", "hour"}))) {
        q.kind = QKind::kSpeed;
        q.value = std::round(q.value / 1.852 * 10.0) /
                  10.0;  // km/h -> [kt] to 0.1 (the lexer reads "km/h" as "km per h")
        j += word_at(t, j, {"kph", "kmh"}) ? 1 : 3;
      } else if (word_at(t, j, {"km", "kilometres", "kilometers", "kilometre", "kilometer"})) {
        q.kind = QKind::kDist;
        q.value = std::round(q.value / 1.852 * 10.0) / 10.0;  // [NM] to 0.1
        ++j;
      } else if (word_at(t, j, {"seconds", "second", "s", "sec", "secs"})) {
        q.kind = QKind::kTime;
        ++j;
      } else if (word_at(t, j, {"minutes", "minute", "min", "mins"})) {
        q.kind = QKind::kTime;
        q.value *= 60.0;
        ++j;
      } else if (word_at(t, j, {"hours", "hour", "h"})) {
        q.kind = QKind::kTime;
        q.value *= 3600.0;
        ++j;
      } else if (word_at(t, j, {"%", "percent"})) {
        q.kind = QKind::kPercent;
        ++j;
      } else if (word_at(t, j, {"x", "times"})) {
        q.kind = QKind::kMult;
        ++j;
      } else if (word_at(t, j, {"left", "right"}) && q.kind == QKind::kPlain && !n->has_thousand &&
                 q.value <= 180.0 && !word_at(t, j + 1, {"turn", "heading"})) {
        q.kind = QKind::kAngle;
        q.turn = t[j].text == "left" ? -1 : 1;
        ++j;
      } else if (q.kind == QKind::kPlain && !n->has_decimal && q.value >= 500 && q.value <= 8000 &&
                 word_at(t, j, {"or"}) && word_at(t, j + 1, {"more", "greater"})) {
        q.kind = QKind::kVs;  // "fifteen hundred or greater": a minimum rate
        j += 2;
      } else if (q.kind == QKind::kPlain && n->has_thousand) {
        q.kind = QKind::kAlt;
      }
    }
    if (q.kind == QKind::kAngle && q.turn == 0 && prev({"left", "right"})) q.turn = t[p - 1].text == "left" ? -1 : 1;
    if (prev({"by"})) q.by = true;
    if (prev({"to"})) q.to = true;
    if (p >= floor + 3 && word_at(t, p - 3, {"plus"}) && word_at(t, p - 2, {"or"}) &&
        word_at(t, p - 1, {"minus"})) {
      p -= 3;  // "plus or minus 1000 feet": a size either side, not a negative value
    } else if (prev({"minus", "negative"})) {
      q.value = -q.value;
      --p;
    }
    q.begin = p;
    q.end = j;
    floor = j;
    out.push_back(q);
    i = j > i ? j : i + 1;
  }
  return out;
}

}  // namespace squawk::translate
