#include "translate/number_words.h"

#include <array>
#include <cstdlib>

namespace squawk::translate {
namespace {

int teen_word(const std::string& w) {
  static const std::array<const char*, 10> kTeens = {"ten",      "eleven",  "twelve",  "thirteen",
                                                     "fourteen", "fifteen", "sixteen", "seventeen",
                                                     "eighteen", "nineteen"};
  for (size_t i = 0; i < kTeens.size(); ++i)
    if (w == kTeens[i]) return static_cast<int>(10 + i);
  return -1;
}

int tens_word(const std::string& w) {
  static const std::array<const char*, 8> kTens = {"twenty", "thirty",  "forty",  "fifty",
                                                   "sixty",  "seventy", "eighty", "ninety"};
  for (size_t i = 0; i < kTens.size(); ++i)
    if (w == kTens[i]) return static_cast<int>(20 + 10 * i);
  if (w == "fourty") return 40;
  return -1;
}

bool is_word(const std::vector<Token>& t, size_t i, const char* w) {
  return i < t.size() && t[i].kind == TokKind::kWord && t[i].text == w;
}

int digit_at(const std::vector<Token>& t, size_t i) {
  return i < t.size() && t[i].kind == TokKind::kWord ? digit_word(t[i].text) : -1;
}

bool group_at(const std::vector<Token>& t, size_t i) {
  return i < t.size() && t[i].kind == TokKind::kWord &&
         (digit_word(t[i].text) >= 0 || teen_word(t[i].text) >= 0 || tens_word(t[i].text) >= 0);
}

// True when the number words (and "and") from i, one speed with at most one "hundred" ("two hundred
// and fifty"; "five hundred one hundred ten" is two values), are followed by a speed's unit.
bool speed_follows(const std::vector<Token>& t, size_t i) {
  int hundreds = 0;
  for (;
       i < t.size() && t[i].kind == TokKind::kWord && (is_number_word(t[i]) || t[i].text == "and");
       ++i) {
    if (t[i].text == "thousand" || (t[i].text == "hundred" && ++hundreds > 1)) return false;
  }
  return i < t.size() && t[i].kind == TokKind::kWord &&
         (t[i].text == "knots" || t[i].text == "knot" || t[i].text == "kts" || t[i].text == "kt");
}

// True when "to" at i opens a latitude or longitude said in digits ("move UAL9 to four zero point
// eight north", "move the Avianca two four to nine north"), or the latitude of a pair said with
// decimals and a comma between ("move Wizz Air three zero four one to four five decimal three,
// eight decimal nine"): as the digit two, with the digits said straight before it, it would make a
// degree beyond the pole or the antimeridian (240.8 north, 2429 north, 245.3 as a latitude).
bool position_after_to(const std::vector<Token>& t, size_t i) {
  if (t[i].text != "to" && t[i].text != "too") return false;
  std::string before;
  for (size_t k = i; k > 0 && digit_at(t, k - 1) >= 0; --k)
    before.insert(before.begin(), static_cast<char>('0' + digit_at(t, k - 1)));
  std::string digits;
  size_t j = i + 1;
  while (digit_at(t, j) >= 0) digits += static_cast<char>('0' + digit_at(t, j++));
  bool decimals = false;
  if (is_word(t, j, "point") || is_word(t, j, "decimal")) {
    ++j;
    for (; digit_at(t, j) >= 0; ++j) decimals = true;
  }
  // (a comma, then digits and a point or "decimal" with digits after it: a longitude follows)
  bool pair = decimals && j < t.size() && t[j].kind == TokKind::kPunct && t[j].text == ",";
  size_t k = j + 1;
  while (pair && digit_at(t, k) >= 0) ++k;
  pair = pair && k > j + 1 && (is_word(t, k, "point") || is_word(t, k, "decimal")) &&
         digit_at(t, k + 1) >= 0;
  const double limit = is_word(t, j, "north") || is_word(t, j, "south") || pair ? 90.0
                       : is_word(t, j, "east") || is_word(t, j, "west")         ? 180.0
                                                                                : 0.0;
  return limit > 0.0 && !digits.empty() &&
         std::strtod((before + "2" + digits).c_str(), nullptr) > limit &&
         std::strtod(digits.c_str(), nullptr) <= limit;
}

// The fraction "and a half" / "and one half" (0.5), "and a quarter" / "and one quarter" (0.25) or
// "and three quarters" (0.75) said at i, with `end` set one past it; 0 when none is said there.
double and_fraction(const std::vector<Token>& t, size_t i, size_t& end) {
  if (!is_word(t, i, "and")) return 0.0;
  double f = 0.0;
  if (is_word(t, i + 1, "a") || is_word(t, i + 1, "one")) {
    f = is_word(t, i + 2, "half") ? 0.5 : is_word(t, i + 2, "quarter") ? 0.25 : 0.0;
  } else if (is_word(t, i + 1, "three") && is_word(t, i + 2, "quarters")) {
    f = 0.75;
  }
  if (f > 0.0) end = i + 3;
  return f;
}

// A whole number `n` read up to j, with no multiplier said, followed by a fraction ("two and a
// half", "one and a half thousand" = 1500, "two and a quarter hundred"): adds the fraction and the
// multiplier after it to n and moves j past them. A number said as a flight level, a heading, a
// Mach number or a code ("FL100 and a half") takes none: no such value has a fraction.
void add_fraction(const std::vector<Token>& t, SpokenNumber& n, size_t& j) {
  static const std::array<const char*, 8> kWhole = {"fl",   "level",  "heading", "hdg",
                                                    "mach", "squawk", "code",    "flight"};
  for (const char* w : kWhole)
    if (n.begin > 0 && is_word(t, n.begin - 1, w)) return;
  size_t k = j;
  const double f = n.has_thousand || n.has_hundred || n.has_decimal ? 0.0 : and_fraction(t, j, k);
  if (f == 0.0) return;
  n.value += f;
  if (is_word(t, k, "thousand")) {
    n.value *= 1000.0;
    n.has_thousand = true;
    ++k;
  } else if (is_word(t, k, "hundred")) {
    n.value *= 100.0;
    n.has_hundred = true;
    ++k;
  }
  j = k;
}

double value_of(const std::string& digits) {
  return digits.empty() ? 0.0 : std::strtod(digits.c_str(), nullptr);
}

// Digits after "point"/"decimal" starting at i; advances i. A single digit typed after digit words
// is one of them ("point seven 8", words and keys mixed).
std::string fraction_digits(const std::vector<Token>& t, size_t& i) {
  std::string f;
  while (digit_at(t, i) >= 0) f += static_cast<char>('0' + digit_at(t, i++));
  if (!f.empty() && i < t.size() && t[i].kind == TokKind::kNumber && t[i].raw.size() == 1 &&
      t[i].raw[0] >= '0' && t[i].raw[0] <= '9')
    f += t[i++].raw;
  return f;
}

struct Homophone {
  const char* heard;
  const char* digit;
  int value;
};
constexpr std::array<Homophone, 11> kHeard = {{{"to", "two", 2},
                                               {"too", "two", 2},
                                               {"on", "one", 1},
                                               {"won", "one", 1},
                                               {"once", "one", 1},
                                               {"ones", "one", 1},
                                               {"for", "four", 4},
                                               {"ate", "eight", 8},
                                               {"hate", "eight", 8},
                                               {"a", "eight", 8},
                                               {"fine", "five", 5}}};

// A part of a number said in words joined by hyphens: a number word, a zero said "oh"/"o", or a
// digit said twice or three times ("double", "triple").
bool hyphen_number_part(const Token& t) {
  return t.kind == TokKind::kWord && (is_number_word(t) || t.text == "oh" || t.text == "o" ||
                                      t.text == "double" || t.text == "triple");
}

// A word joined by hyphens whose every part is a hyphen_number_part ("forty-five",
// "four-fifty-one", "thirty-three-oh-two", "one-double-zero", "two-four-zero") is those words said
// apart: the parts lose their glue (no part is noise between digits), and an "oh"/"o" part after
// the first is the digit zero ("two-two-oh" = 220). A word with any other part ("nine-year",
// "one-way") keeps its glue.
void words_of_hyphened_numbers(std::vector<Token>& t) {
  for (size_t b = 0; b < t.size();) {
    size_t e = b + 1;
    while (e < t.size() && t[e].glued && t[e].kind == TokKind::kWord) ++e;
    bool numbers = e - b >= 2;
    for (size_t k = b; numbers && k < e; ++k) numbers = hyphen_number_part(t[k]);
    for (size_t k = b; numbers && k < e; ++k) {
      t[k].glued = false;
      if (k > b && (t[k].text == "oh" || t[k].text == "o")) t[k].text = "zero";
    }
    b = e;
  }
}

}  // namespace

int heard_digit(const std::string& w) {
  for (const auto& h : kHeard)
    if (w == h.heard) return h.value;
  return -1;
}

void fold_digit_homophones(std::vector<Token>& t) {
  auto digit = [&](size_t i) {
    return i < t.size() && t[i].kind == TokKind::kWord && digit_word(t[i].text) >= 0;
  };
  words_of_hyphened_numbers(t);
  // "hate", "too" and "won", which a clearance never says as English, before a number ("too too
  // zero", "descend too thousand", "one hate zero" read right to left) are its digit; "hate" and
  // "won" after a digit too ("one fife hate proceed"), and "too" before a side of the globe ("fifty
  // tree north too west")
  for (size_t i = t.size(); i-- > 0;) {
    const std::string& w = t[i].text;
    if (t[i].kind != TokKind::kWord || (w != "hate" && w != "too" && w != "won")) continue;
    // ("speed too two zero": "to two" or "two two", a digit perhaps lost: left as heard, asked)
    const bool two_after =
        w == "too" && i + 1 < t.size() && (t[i + 1].raw == "two" || t[i + 1].raw == "2");
    const bool before = i + 1 < t.size() && t[i + 1].kind == TokKind::kWord &&
                        is_number_word(t[i + 1]) && !two_after;
    const bool after = i > 0 && digit(i - 1) && w != "too";
    const bool side = w == "too" && (is_word(t, i + 1, "north") || is_word(t, i + 1, "south") ||
                                     is_word(t, i + 1, "east") || is_word(t, i + 1, "west"));
    if (before || after || side) t[i].text = w == "too" ? "two" : w == "won" ? "one" : "eight";
  }
  for (size_t i = 1; i + 1 < t.size();) {
    const std::string& r = t[i].raw;
    const bool letter = r.size() == 1 && r[0] >= 'b' && r[0] <= 'z' && r != "i";
    const bool noise =
        t[i].kind == TokKind::kWord && digit_word(t[i].text) < 0 && (letter || t[i].glued);
    if (noise && digit(i - 1) && digit(i + 1)) {
      t.erase(t.begin() + static_cast<long>(i));
    } else {
      ++i;
    }
  }
  for (size_t i = 1; i < t.size(); ++i) {
    if (t[i].kind != TokKind::kWord || !digit(i - 1)) continue;
    for (const auto& h : kHeard) {
      if (t[i].text != h.heard) continue;
      // between two digits; "fine" also closing a run of two ("three three fine"),
      // and the one-words and "ate" closing the utterance ("speed two once")
      const bool last = i + 1 == t.size() || t[i + 1].kind == TokKind::kPunct;
      const bool closes =
          (t[i].text == "fine" && i >= 2 && digit(i - 2) && !digit(i + 1)) ||
          (last && (t[i].text == "won" || t[i].text == "once" || t[i].text == "ones" ||
                    t[i].text == "ate" || t[i].text == "fine" || t[i].text == "for"));
      if ((digit(i + 1) && !position_after_to(t, i)) || closes) t[i].text = h.digit;
    }
  }
  // Thousands said as two words of which one is heard as a homophone ("one to thousand", "won too
  // thousand", "won for thousand": 12000, 12000, 14000): both are digits; a first "to", "too" or
  // "for" stays a preposition ("descend to four thousand"), as does one after another digit.
  auto heard = [&](size_t i) {
    return i < t.size() && t[i].kind == TokKind::kWord &&
           (t[i].text == "to" || t[i].text == "too" || t[i].text == "won" || t[i].text == "for" ||
            t[i].text == "ate");
  };
  auto fold = [&](size_t i) {
    for (const auto& h : kHeard)
      if (heard(i) && t[i].text == h.heard) t[i].text = h.digit;
  };
  for (size_t i = 0; i + 2 < t.size(); ++i) {
    const std::string& w = t[i].text;
    const bool first = digit(i) || w == "won" || w == "ate";
    if (!first || !(digit(i + 1) || heard(i + 1)) || !(heard(i) || heard(i + 1)) ||
        !is_word(t, i + 2, "thousand") ||
        (i > 0 && (digit(i - 1) || heard(i - 1)) && t[i - 1].text != "to"))
      continue;
    fold(i);
    fold(i + 1);
  }
  // "reduce speed to too fifty", "descend to too thousand": "too" straight after the preposition
  // "to" and before a number word is the digit two
  for (size_t i = 1; i + 1 < t.size(); ++i)
    if (t[i].kind == TokKind::kWord && t[i].text == "too" && is_word(t, i - 1, "to") &&
        t[i + 1].kind == TokKind::kWord && is_number_word(t[i + 1]))
      t[i].text = "two";
}

int digit_word(const std::string& w) {
  static const std::array<const char*, 10> kDigits = {"zero", "one", "two",   "three", "four",
                                                      "five", "six", "seven", "eight", "nine"};
  for (size_t i = 0; i < kDigits.size(); ++i)
    if (w == kDigits[i]) return static_cast<int>(i);
  if (w == "niner") return 9;
  if (w == "fife" || w == "fiver") return 5;
  if (w == "tree") return 3;
  if (w == "fower") return 4;
  return -1;
}

bool is_number_word(const Token& t) {
  if (t.kind == TokKind::kNumber) return true;
  if (t.kind != TokKind::kWord) return false;
  return digit_word(t.text) >= 0 || teen_word(t.text) >= 0 || tens_word(t.text) >= 0 ||
         t.text == "hundred" || t.text == "thousand";
}

std::optional<SpokenNumber> read_number(const std::vector<Token>& t, size_t i) {
  if (i >= t.size()) return std::nullopt;
  SpokenNumber n;
  n.begin = i;
  if (t[i].kind == TokKind::kNumber) {
    n.typed = true;
    n.value = t[i].num;
    n.digits = t[i].raw;
    n.has_decimal = t[i].spelled;
    n.groups = 1;
    size_t j = i + 1;
    add_fraction(t, n, j);
    if (is_word(t, j, "thousand")) {
      n.value *= 1000.0;
      n.has_thousand = true;
      ++j;
      // "9 thousand 500 feet", "9 thousand 5 hundred": typed hundreds after the thousands are its
      // hundreds (a bare number is so only before feet: "4 thousand 300 knots" is two values)
      if (j < t.size() && t[j].kind == TokKind::kNumber && !t[j].spelled) {
        const double h = t[j].num;
        if (h >= 1 && h <= 9 && h == static_cast<int>(h) && is_word(t, j + 1, "hundred")) {
          n.value += h * 100.0;
          j += 2;
        } else if (h >= 100 && h <= 900 && static_cast<int>(h) % 100 == 0 &&
                   (is_word(t, j + 1, "feet") || is_word(t, j + 1, "ft"))) {
          n.value += h;
          ++j;
        }
      }
    } else if (is_word(t, j, "hundred")) {
      n.value *= 100.0;
      n.has_hundred = true;
      ++j;
    }
    n.end = j;
    return n;
  }
  // Leading "point seven eight" (a Mach number); "point eighty two" (its two digits said as a
  // number) is the same.
  const bool lead = is_word(t, i, "point") || is_word(t, i, "decimal");
  if (lead && i + 1 < t.size() && t[i + 1].kind == TokKind::kWord &&
      tens_word(t[i + 1].text) >= 0) {
    const int tens = tens_word(t[i + 1].text), unit = digit_at(t, i + 2);
    size_t j = i + 2 + (unit > 0 ? 1 : 0);
    if (is_word(t, j, "thousand") || is_word(t, j, "hundred")) return std::nullopt;
    n.digits = std::to_string(tens + (unit > 0 ? unit : 0));
    n.value = value_of("0." + n.digits);
    n.has_decimal = true;
    n.groups = 1;
    n.end = j;
    return n;
  }
  if (lead && digit_at(t, i + 1) >= 0) {
    size_t j = i + 1;
    std::string f = fraction_digits(t, j);
    if (is_word(t, j, "thousand") || is_word(t, j, "hundred")) return std::nullopt;
    n.value = value_of("0." + f);
    n.digits = f;
    n.has_decimal = true;
    n.groups = 1;
    n.end = j;
    return n;
  }
  double acc = 0.0;
  std::string cur;  // digits of the groups since the last multiplier
  size_t j = i;
  bool any = false;
  while (j < t.size() && t[j].kind == TokKind::kWord && cur.size() < 15 && n.digits.size() < 30) {
    const std::string& w = t[j].text;
    int d = digit_word(w), teen = teen_word(w), tens = tens_word(w);
    if (d >= 0 || teen >= 0 || tens >= 0) {
      // digits said singly or grouped after "thousand" are the next value, not its
      // hundreds ("one one thousand two five zero knots", "seven thousand two twenty
      // knots": 11000 then 250, 7000 then 220)
      if (n.has_thousand && cur.empty() && d >= 0 && group_at(t, j + 1)) break;
      // nor are words said after "thousand" that end in a speed's unit ("one zero thousand two
      // hundred and fifty knots": 10000 then 250; no speed runs to thousands of knots)
      if (n.has_thousand && cur.empty() && speed_follows(t, j)) break;
      int v = d >= 0 ? d : teen >= 0 ? teen : tens;
      if (tens >= 0 && digit_at(t, j + 1) > 0) {
        v += digit_at(t, j + 1);
        ++j;
      }
      if (!any) n.leading_digit_word = d >= 0;
      std::string g = std::to_string(v);
      cur += g;
      n.digits += g;
      ++n.groups;
      any = true;
      ++j;
    } else if (w == "hundred" && !any && i > 0 && is_word(t, i - 1, "level")) {
      // "flight level hundred", "level hundred and ten": the hundred of a flight level said without
      // its one
      acc = 100.0;
      n.digits += "1";
      ++n.groups;
      n.has_hundred = true;
      any = true;
      ++j;
    } else if (w == "hundred" && any && !cur.empty()) {
      acc += value_of(cur) * 100.0;
      cur.clear();
      n.has_hundred = true;
      ++j;
    } else if (w == "thousand" && any) {
      acc = (acc + value_of(cur)) * 1000.0;
      cur.clear();
      n.has_thousand = true;
      ++j;
    } else if (w == "and" && (n.has_hundred || n.has_thousand) && group_at(t, j + 1)) {
      // "one zero thousand and niner thousand": a second thousands after "and" is a value of its
      // own
      size_t k = j + 1;
      while (k < t.size() && t[k].kind == TokKind::kWord && is_number_word(t[k]) &&
             t[k].text != "thousand")
        ++k;
      if (n.has_thousand && is_word(t, k, "thousand")) break;
      ++j;
    } else if ((w == "ah" || w == "uh" || w == "um" || w == "er") && group_at(t, j + 1)) {
      ++j;  // a hesitation inside a number: "one ah zero eight zero"
    } else if ((w == "point" || w == "decimal") && any && digit_at(t, j + 1) >= 0) {
      size_t k = j + 1;
      std::string f = fraction_digits(t, k);
      if (is_word(t, k, "thousand") || is_word(t, k, "hundred")) break;
      double whole = acc + value_of(cur);
      n.value = whole + value_of("0." + f);
      n.has_decimal = true;
      n.end = k;
      return n;
    } else {
      break;
    }
  }
  if (!any) return std::nullopt;
  n.value = acc + value_of(cur);
  add_fraction(t, n, j);
  n.end = j;
  return n;
}

}  // namespace squawk::translate
