#include "translate/lexer.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/text.h"

namespace squawk::translate {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool is_clause_punct(char c) { return c == ',' || c == '.' || c == ';' || c == ':' || c == '?' || c == '!'; }

Token word(std::string_view raw) {
  Token t;
  t.kind = TokKind::kWord;
  t.raw = std::string(raw);
  t.text = text::lower(raw);
  return t;
}

Token number(double v, std::string_view raw, bool spelled) {
  Token t;
  t.kind = TokKind::kNumber;
  t.num = v;
  t.raw = std::string(raw);
  t.text = std::string(raw);
  t.spelled = spelled;
  return t;
}

Token punct(char c) {
  Token t;
  t.kind = TokKind::kPunct;
  t.text = std::string(1, c);
  t.raw = t.text;
  return t;
}

// Length of the leading decimal number in s ("52.3N" -> 4); 0 when none.
size_t number_prefix(std::string_view s) {
  size_t i = 0;
  while (i < s.size() && is_digit(s[i])) ++i;
  if (i < s.size() && s[i] == '.' && i + 1 < s.size() && is_digit(s[i + 1])) {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i;
  }
  return i;
}

bool all_of(std::string_view s, bool (*pred)(char)) {
  if (s.empty()) return false;
  for (char c : s)
    if (!pred(c)) return false;
  return true;
}

// "41,000" / "1,200,000" (sep ','), "5.000" (sep '.'), "5'000" (sep '\''): digit groups of three
// after the first, which has one to three digits (and, with '.' or '\'', no leading zero: "0.500"
// is a decimal).
bool thousands_grouped(std::string_view s, char sep = ',') {
  auto parts = text::split(s, sep);
  if (parts.size() < 2 || parts[0].empty() || parts[0].size() > 3 || !all_of(parts[0], is_digit)) return false;
  if (sep != ',' && parts[0][0] == '0') return false;
  for (size_t i = 1; i < parts.size(); ++i)
    if (parts[i].size() != 3 || !all_of(parts[i], is_digit)) return false;
  return true;
}

// The whole number a thousands grouping with separator `sep` writes ("5.000" -> 5000).
double grouped_value(std::string_view s, char sep) {
  std::string digits;
  for (char ch : s)
    if (ch != sep) digits += ch;
  return text::to_double(digits).value_or(0.0);
}

// "5'000", "12’500" (a typographic apostrophe): the apostrophe groups thousands as Swiss
// German writes them (it is never a decimal point); the text with a plain apostrophe, or "" when
// `s` is no such grouping.
std::string apostrophe_grouped(std::string_view s) {
  std::string plain;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s.substr(i, 3) == "\xE2\x80\x99") {
      plain += '\'';
      i += 2;
    } else {
      plain += s[i];
    }
  }
  return thousands_grouped(plain, '\'') ? plain : std::string();
}

// "0,76": a zero, a decimal comma and one to three digits, as French and Arabic write a decimal (a
// list or a thousands grouping never opens with a lone zero).
bool zero_decimal_comma(std::string_view s) {
  return s.size() >= 3 && s.size() <= 5 && s[0] == '0' && s[1] == ',' &&
         all_of(s.substr(2), is_digit);
}

// Degrees with minutes (and seconds) written with ° ' " marks, hemisphere
// letter before or after: "N52°18.6'", "52°18'N", "004°45.8'E".
bool lex_dms(std::string_view s, std::vector<Token>& out) {
  std::string hemi;
  if (!s.empty() && std::string_view("NSEWnsew").find(s.front()) != std::string_view::npos) {
    hemi = text::lower(s.substr(0, 1));
    s.remove_prefix(1);
  }
  if (!s.empty() && std::string_view("NSEWnsew").find(s.back()) != std::string_view::npos) {
    if (!hemi.empty()) return false;
    hemi = text::lower(s.substr(s.size() - 1));
    s.remove_suffix(1);
  }
  double parts[3] = {0, 0, 0};
  int n = 0;
  size_t i = 0;
  while (i < s.size() && n < 3) {
    size_t len = number_prefix(s.substr(i));
    if (len == 0) return false;
    parts[n++] = text::to_double(s.substr(i, len)).value_or(0.0);
    i += len;
    // skip the mark: "°" (2 bytes in UTF-8), "'", '"', or "º"
    size_t mark = 0;
    while (i + mark < s.size() && !is_digit(s[i + mark]) && s[i + mark] != '.') ++mark;
    if (mark == 0 && i < s.size()) return false;
    i += mark;
  }
  if (n == 0 || i < s.size()) return false;
  double deg = parts[0] + parts[1] / 60.0 + parts[2] / 3600.0;
  out.push_back(number(deg, s, true));
  if (!hemi.empty()) out.push_back(word(hemi));
  return true;
}

void lex_chunk(std::string_view c, std::vector<Token>& out);

void lex_core(std::string_view c, std::vector<Token>& out) {
  if (c.empty()) return;
  // File names and paths stay whole.
  if (c.find(".scn") != std::string_view::npos || c.find(".SCN") != std::string_view::npos) {
    out.push_back(word(c));
    return;
  }
  if (c.find('/') != std::string_view::npos) {
    auto parts = text::split(c, '/');
    bool words = true;
    for (auto& p : parts) words = words && all_of(p, is_letter);
    if (words) {  // "ft/min" reads as "ft per min"
      for (size_t i = 0; i < parts.size(); ++i) {
        if (i) out.push_back(word("per"));
        out.push_back(word(parts[i]));
      }
    } else {
      out.push_back(word(c));
    }
    return;
  }
  if (c.size() > 1 && c.front() == '-' && (is_digit(c[1]) || c[1] == '.')) {  // "-1000 fpm", "-73.5"
    const size_t first = out.size();
    lex_core(c.substr(1), out);
    if (out.size() > first && out[first].kind == TokKind::kNumber) {
      out[first].num = -out[first].num;
      out[first].raw.insert(out[first].raw.begin(), '-');
      out[first].text = out[first].raw;
    }
    return;
  }
  if (c.find('\xB0') != std::string_view::npos && lex_dms(c, out)) return;
  if (thousands_grouped(c)) {
    out.push_back(number(grouped_value(c, ','), c, false));
    return;
  }
  // "1.200.000": dots between groups of three, more than one, are a thousands grouping (no decimal
  // has two points); one dot ("5.000") is a decimal here and read as a grouping only before feet
  // (read_beside).
  if (std::count(c.begin(), c.end(), '.') > 1 && thousands_grouped(c, '.')) {
    out.push_back(number(grouped_value(c, '.'), c, false));
    return;
  }
  if (auto plain = apostrophe_grouped(c); !plain.empty()) {
    out.push_back(number(grouped_value(plain, '\''), c, false));
    return;
  }
  if (zero_decimal_comma(c)) {
    out.push_back(
        number(text::to_double(std::string("0.").append(c.substr(2))).value_or(0.0), c, true));
    return;
  }
  if (c.front() == '.' && c.size() > 1 && all_of(c.substr(1), is_digit)) {
    out.push_back(number(text::to_double(std::string("0").append(c)).value_or(0.0), c, true));
    return;
  }
  size_t np = number_prefix(c);
  if (np == c.size()) {
    out.push_back(number(text::to_double(c).value_or(0.0), c, c.find('.') != std::string_view::npos));
    return;
  }
  if (np > 0) {
    std::string_view rest = c.substr(np);
    if (all_of(rest, is_letter) || rest == "%") {  // 30k, 250kt, 52.3N, 10%
      out.push_back(number(text::to_double(c.substr(0, np)).value_or(0.0), c.substr(0, np), true));
      out.push_back(word(rest));
      return;
    }
  }
  // Letter prefix then a number: FL250, M0.85, M.78, N52.3.
  size_t letters = 0;
  while (letters < c.size() && is_letter(c[letters])) ++letters;
  if (letters > 0 && letters < c.size()) {
    std::string pre = text::lower(c.substr(0, letters));
    std::string_view rest = c.substr(letters);
    bool rest_number = number_prefix(rest) == rest.size() ||
                       (rest.front() == '.' && rest.size() > 1 && all_of(rest.substr(1), is_digit));
    double v = rest.front() == '.' ? text::to_double(std::string("0").append(rest)).value_or(0.0)
                                   : text::to_double(rest).value_or(0.0);
    if (rest_number && pre == "fl") {
      out.push_back(word("fl"));
      out.push_back(number(v, rest, false));
      return;
    }
    if (rest_number && pre == "m" && rest.find('.') != std::string_view::npos) {
      out.push_back(word("mach"));
      out.push_back(number(v, rest, true));
      return;
    }
    if (rest_number && pre.size() == 1 && std::string_view("nsew").find(pre) != std::string_view::npos &&
        rest.find('.') != std::string_view::npos) {
      out.push_back(word(pre));
      out.push_back(number(v, rest, true));
      return;
    }
  }
  // Digit groups joined by hyphens, four digits at most and the first group
  // of one or two, are one number as speech recognition writes it ("21-0" =
  // two one zero, "91-48"); others are names (737-800, 787-9).
  if (c.find('-') != std::string_view::npos && c.front() != '-' && c.find('-') <= 2) {
    std::string digits;
    bool all_digits = true;
    for (auto& p : text::split(c, '-')) {
      all_digits = all_digits && !p.empty() && all_of(p, is_digit);
      digits += p;
    }
    if (all_digits && digits.size() <= 4) {
      out.push_back(number(text::to_double(digits).value_or(0.0), digits, false));
      return;
    }
  }
  // Hyphenated words split unless the token carries digits (737-800).
  if (c.find('-') != std::string_view::npos && !has_digit(c)) {
    for (auto& p : text::split(c, '-'))
      if (!p.empty()) lex_chunk(p, out);
    return;
  }
  out.push_back(word(c));
}

void lex_chunk(std::string_view c, std::vector<Token>& out) {
  const size_t first = out.size();
  // Leading brackets and quotes are dropped; trailing clause punctuation is kept as tokens.
  while (!c.empty() && std::string_view("([{'`").find(c.front()) != std::string_view::npos) c.remove_prefix(1);
  std::vector<Token> tail;
  while (!c.empty()) {
    char b = c.back();
    if (is_clause_punct(b)) {
      tail.insert(tail.begin(), punct(b));
      c.remove_suffix(1);
    } else if (std::string_view(")]}`").find(b) != std::string_view::npos ||
               (b == '\'' && c.find('\xB0') == std::string_view::npos)) {
      c.remove_suffix(1);
    } else if (b == '-') {
      c.remove_suffix(1);
    } else {
      break;
    }
  }
  // Possessive "AC02's" names AC02.
  if (c.size() > 2 && (c.ends_with("'s") || c.ends_with("'S"))) c.remove_suffix(2);
  if (c.size() > 4 && c.ends_with("\xE2\x80\x99s")) c.remove_suffix(4);
  lex_core(c, out);
  for (size_t i = first + 1; i < out.size(); ++i) out[i].glued = true;
  out.insert(out.end(), tail.begin(), tail.end());
}

// Units of a height or a vertical speed in feet ("ft/min" lexes as "ft" "per" "min").
bool feet_unit(const Token& t) {
  return t.kind == TokKind::kWord &&
         (t.text == "ft" || t.text == "feet" || t.text == "foot" || t.text == "fpm");
}

// Numbers whose reading depends on the token beside them, read in place over the token list:
//  - "5.000 ft", "2.500 fpm", "12.000ft": one dot and a group of three digits before a unit of feet
//    groups thousands (5000), as German writes them: feet or feet per minute to three decimal
//    places are no value anyone says, and "0.500 ft" (a leading zero) is no grouping;
//  - "Mach ,78": a comma and one to three digits after "mach" is its decimal (0.78), as a decimal
//    comma writes ".78".
void read_beside(std::vector<Token>& out) {
  for (size_t i = 0; i < out.size(); ++i) {
    Token& t = out[i];
    if (t.kind == TokKind::kNumber && i + 1 < out.size() && feet_unit(out[i + 1]) &&
        thousands_grouped(t.raw, '.')) {
      t.num = grouped_value(t.raw, '.');
      t.spelled = false;
    } else if (t.kind == TokKind::kWord && i > 0 && out[i - 1].kind == TokKind::kWord &&
               out[i - 1].text == "mach" && t.raw.size() >= 2 && t.raw.size() <= 4 &&
               t.raw[0] == ',' && all_of(std::string_view(t.raw).substr(1), is_digit)) {
      t = number(text::to_double("0." + t.raw.substr(1)).value_or(0.0), t.raw, true);
    }
  }
}

}  // namespace

bool has_digit(std::string_view s) {
  for (char c : s)
    if (is_digit(c)) return true;
  return false;
}

bool is_alpha(std::string_view s) { return all_of(s, is_letter); }

std::vector<Token> lex(std::string_view u) {
  std::vector<Token> out;
  size_t i = 0;
  while (i < u.size()) {
    if (is_space(u[i])) {
      ++i;
      continue;
    }
    if (u[i] == '"') {
      size_t e = u.find('"', i + 1);
      if (e == std::string_view::npos) e = u.size();
      Token t;
      t.kind = TokKind::kQuoted;
      t.raw = std::string(u.substr(i + 1, e - i - 1));
      t.text = t.raw;
      out.push_back(std::move(t));
      i = e + 1;
      continue;
    }
    size_t j = i;
    while (j < u.size() && !is_space(u[j]) && u[j] != '"') ++j;
    lex_chunk(u.substr(i, j - i), out);
    i = j;
  }
  read_beside(out);
  return out;
}

}  // namespace squawk::translate
