// Lexer and spoken numbers.
#include <doctest/doctest.h>

#include "translate/lexer.h"
#include "translate/number_words.h"
#include "translate/quantities.h"

using namespace squawk::translate;

namespace {

SpokenNumber num(const char* text) {
  auto toks = lex(text);
  auto n = read_number(toks, 0);
  REQUIRE(n.has_value());
  return *n;
}

std::vector<Quantity> qty(const char* text) {
  auto toks = lex(text);
  std::vector<bool> skip(toks.size(), false);
  return extract_quantities(toks, 0, toks.size(), skip);
}

// The one quantity `text` holds (fails when it holds none or several).
Quantity one_qty(const char* text) {
  auto q = qty(text);
  INFO(text);
  REQUIRE(q.size() == 1);
  return q[0];
}

}  // namespace

TEST_CASE("number words: cardinals") {
  CHECK(num("thirty-one thousand").value == 31000);
  CHECK(num("one hundred and twenty").value == 120);
  CHECK(num("two hundred ninety").value == 290);
  CHECK(num("twelve hundred").value == 1200);
  CHECK(num("four thousand five hundred").value == 4500);
  CHECK(num("seventeen").value == 17);
  CHECK_FALSE(read_number(lex("heading"), 0).has_value());
}

TEST_CASE("number words: ATC digit by digit and groups") {
  CHECK(num("one two zero").value == 120);
  CHECK(num("three five zero").value == 350);
  CHECK(num("niner").value == 9);
  CHECK(num("fife tree").value == 53);
  CHECK(num("one one thousand").value == 11000);
  CHECK(num("one zero thousand").value == 10000);
  // two levels joined by "and" are two values ("10000 and 9000 respectively"), never 10009000
  SpokenNumber first = num("one zero thousand and niner thousand");
  CHECK(first.value == 10000);
  CHECK(first.end == 3);
  CHECK(num("five thousand and two hundred").value == 5200);
  CHECK(num("two thousand and fifty").value == 2050);
  SpokenNumber g = num("fifty one twenty");
  CHECK(g.digits == "5120");
  CHECK(g.groups == 2);
  CHECK(num("one eighty").value == 180);
  CHECK(num("two ten").value == 210);
  CHECK(num("one ah zero eight zero").value == 1080);  // hesitation skipped
}

TEST_CASE("number words: decimals") {
  CHECK(num("point seven eight").value == doctest::Approx(0.78));
  CHECK(num("point seven 8").value == doctest::Approx(0.78));  // words and keys mixed
  CHECK(num("decimal eight two").value == doctest::Approx(0.82));
  // the two digits said as a number: "point eighty two" is .82, "point eighty" .80
  CHECK(num("point eighty two").value == doctest::Approx(0.82));
  CHECK(num("point eighty").value == doctest::Approx(0.80));
  CHECK(num("point seventy nine").end == 3);
  // "decimal" before thousand is a misheard verb, not a decimal point
  auto n = num("nine decimal four thousand");
  CHECK(n.value == 9);
}

TEST_CASE("number words: a fraction after a whole number, and a multiplier after it") {
  CHECK(num("two and a half").value == 2.5);
  CHECK(num("2 and a half").value == 2.5);
  CHECK(num("three and a quarter").value == 3.25);
  CHECK(num("one and three quarters").value == 1.75);
  CHECK(num("four and one half").end == 4);
  auto n = num("one and a half thousand feet");
  CHECK(n.value == 1500);
  CHECK(n.has_thousand);
  CHECK(n.end == 5);
  CHECK(num("7 and a half hundred").value == 750);
  // none after a multiplier, and no fraction without its article
  CHECK(num("four thousand and a half").value == 4000);
  CHECK(num("four thousand and a half").end == 2);
  CHECK(num("two and half").value == 2);
  CHECK(qty("radius two and a half nm")[0].value == 2.5);
  CHECK(qty("radius two and a half nm")[0].kind == QKind::kDist);
  // a flight level or a heading has no fraction
  CHECK(qty("FL100 and a half")[0].value == 10000);
  CHECK(qty("heading two and a half")[0].value == 2);
}

TEST_CASE("lexer: glued units, ids, possessives, quotes, degrees") {
  auto t = lex("Climb AC01's altitude to 30k, FL250 and M.78 \"hello there\" 41,000 N52\xC2\xB0" "18.6'");
  std::vector<std::string> words;
  for (const auto& k : t) words.push_back(k.kind == TokKind::kNumber ? "#" : k.text);
  CHECK(words == std::vector<std::string>{"climb", "ac01", "altitude", "to", "#", "k", ",", "fl", "#", "and",
                                          "mach", "#", "hello there", "#", "#", "n"});
  CHECK(t[1].raw == "AC01");
  CHECK(t[13].num == 41000);
  CHECK(t[14].num == doctest::Approx(52.31));
  CHECK(lex("737-800")[0].text == "737-800");
  CHECK(lex("-1000")[0].num == -1000);
  CHECK(lex("-73.5")[0].num == doctest::Approx(-73.5));
  CHECK(lex("thirty-one").size() == 2);
  CHECK(lex("").empty());
}

TEST_CASE("lexer: a point or an apostrophe grouping thousands; a decimal comma after Mach") {
  // a point and a group of three before a unit of feet groups thousands (no value has three
  // decimals)
  CHECK(lex("5.000 ft")[0].num == 5000);
  CHECK_FALSE(lex("5.000 ft")[0].spelled);
  CHECK(lex("5.000 ft")[0].raw == "5.000");
  CHECK(lex("12.000ft")[0].num == 12000);
  CHECK(lex("1.800 fpm")[0].num == 1800);
  CHECK(lex("3.000 ft/min")[0].num == 3000);
  CHECK(lex("2.500 feet per minute")[0].num == 2500);
  // no unit of feet, a leading zero, or figures that are no group of three: the decimal as written
  CHECK(lex("5.000")[0].num == 5);
  CHECK(lex("4.500 nm")[0].num == doctest::Approx(4.5));
  CHECK(lex("0.500 ft")[0].num == doctest::Approx(0.5));
  CHECK(lex("2.50 ft")[0].num == doctest::Approx(2.5));
  CHECK(lex("118.100")[0].num == doctest::Approx(118.1));
  // two points or more: no decimal, a grouping
  CHECK(lex("1.200.000")[0].num == 1200000);
  CHECK(lex("1.20.000")[0].kind == TokKind::kWord);
  // an apostrophe (plain or typographic) groups thousands wherever it stands
  CHECK(lex("5'000 ft")[0].num == 5000);
  CHECK(lex(std::string("12") + "\xE2\x80\x99" + "500")[0].num == 12500);
  CHECK(lex("5'00")[0].kind == TokKind::kWord);
  // "Mach ,78": the comma is the decimal point after "mach" only
  auto m = lex("Mach ,78");
  REQUIRE(m.size() == 2);
  CHECK(m[1].kind == TokKind::kNumber);
  CHECK(m[1].num == doctest::Approx(0.78));
  CHECK(lex("heading ,78")[1].kind == TokKind::kWord);
  // the quantities read the grouped value with its unit
  CHECK(qty("descend to 9.000 ft")[0].kind == QKind::kAlt);
  CHECK(qty("descend to 9.000 ft")[0].value == 9000);
  CHECK(qty("with 2.000 ft/min")[0].kind == QKind::kVs);
  CHECK(qty("with 2.000 ft/min")[0].value == 2000);
}

TEST_CASE("quantities: units decide the kind") {
  Quantity one = one_qty("flight level three five zero");
  CHECK(one.kind == QKind::kAlt);
  CHECK(one.value == 35000);
  CHECK(one.flight_level);

  // "level" alone before one or two digit words and "thousand": an altitude in feet; "flight level"
  // stays a level
  one = one_qty("when level one zero thousand");
  CHECK(one.kind == QKind::kAlt);
  CHECK(one.value == 10000);
  CHECK_FALSE(one.flight_level);
  auto q = qty("flight level three one zero one thousand five hundred feet per minute");
  REQUIRE(q.size() == 2);
  CHECK(q[0].value == 31000);
  CHECK(q[0].flight_level);

  one = one_qty("30k ft");
  CHECK(one.kind == QKind::kAlt);
  CHECK(one.value == 30000);

  for (const char* said : {"M.78", "mach point seven eight"}) {
    one = one_qty(said);
    CHECK(one.kind == QKind::kMach);
    CHECK(one.value == doctest::Approx(0.78));
  }

  q = qty("250 kts 1500 fpm 2000 feet per minute");
  REQUIRE(q.size() == 3);
  CHECK(q[0].kind == QKind::kSpeed);
  CHECK(q[1].kind == QKind::kVs);
  CHECK(q[2].kind == QKind::kVs);
  CHECK(q[2].value == 2000);

  // a rate's minute after "the", "each" or "in the"; "in a minute" is a delay, the feet an altitude
  for (const char* said :
       {"1000 feet the minute", "1000 feet in the minute", "1000 feet each minute"}) {
    one = one_qty(said);
    CHECK(one.kind == QKind::kVs);
    CHECK(one.value == 1000);
  }
  CHECK(one_qty("3000 feet in a minute").kind == QKind::kAlt);

  one = one_qty("3000 m");
  CHECK(one.kind == QKind::kAlt);
  CHECK(one.value == 9843);  // metres converted to whole feet

  q = qty("10 minutes 0.5 s 2.5 NM 10% 5x");
  REQUIRE(q.size() == 5);
  CHECK(q[0].kind == QKind::kTime);
  CHECK(q[0].value == 600);
  CHECK(q[1].kind == QKind::kTime);
  CHECK(q[2].kind == QKind::kDist);
  CHECK(q[3].kind == QKind::kPercent);
  CHECK(q[4].kind == QKind::kMult);
}

TEST_CASE("quantities: latitude and longitude forms") {
  auto q = qty("52 deg 18 min N, 4 deg 45 min E");
  REQUIRE(q.size() == 2);
  CHECK(q[0].kind == QKind::kLat);
  CHECK(q[0].value == doctest::Approx(52.3));
  CHECK(q[1].kind == QKind::kLon);
  CHECK(q[1].value == doctest::Approx(4.75));

  // minutes said without their word, straight before the hemisphere
  q = qty("55 degrees 30 north 003 degrees 00 west");
  REQUIRE(q.size() == 2);
  CHECK(q[0].kind == QKind::kLat);
  CHECK(q[0].value == doctest::Approx(55.5));
  CHECK(q[1].kind == QKind::kLon);
  CHECK(q[1].value == doctest::Approx(-3.0));

  q = qty("N52.3 E4.76");
  REQUIRE(q.size() == 2);
  CHECK(q[0].kind == QKind::kLat);
  CHECK(q[0].value == doctest::Approx(52.3));
  CHECK(q[1].kind == QKind::kLon);
  CHECK(q[1].value == doctest::Approx(4.76));

  q = qty("33.95 S 151.18 E");
  REQUIRE(q.size() == 2);
  CHECK(q[0].value == doctest::Approx(-33.95));

  q = qty("40.5 south 60 west");
  REQUIRE(q.size() == 2);
  CHECK(q[0].value == doctest::Approx(-40.5));
  CHECK(q[1].value == doctest::Approx(-60));

  q = qty("51 degrees 30 minutes north, 0 degrees 7 minutes west");
  REQUIRE(q.size() == 2);
  CHECK(q[0].value == doctest::Approx(51.5));
  CHECK(q[1].value == doctest::Approx(-7.0 / 60.0));

  // degrees and minutes said as groups, as read off a chart: "fifty three thirty" is 53 deg 30 min
  q = qty("fifty three thirty north, five forty five west");
  REQUIRE(q.size() == 2);
  CHECK(q[0].value == doctest::Approx(53.5));
  CHECK(q[1].value == doctest::Approx(-5.75));
  q = qty("fifty one fifty-four north eight thirty west");
  REQUIRE(q.size() == 2);
  CHECK(q[0].value == doctest::Approx(51.9));
  CHECK(q[1].value == doctest::Approx(-8.5));
  // in range as said, or minutes of 60 or more: the value as read (asked later where out of range)
  q = qty("fifty three north one twenty east");
  REQUIRE(q.size() == 2);
  CHECK(q[0].value == doctest::Approx(53));
  CHECK(q[1].value == doctest::Approx(120));
  CHECK(qty("fifty three seventy north")[0].value == doctest::Approx(5370));

  q = qty("N52\xC2\xB0" "18.6' E004\xC2\xB0" "45.8'");
  REQUIRE(q.size() == 2);
  CHECK(q[0].kind == QKind::kLat);
  CHECK(q[1].kind == QKind::kLon);
  CHECK(q[1].value == doctest::Approx(4.763333).epsilon(1e-5));
}

// The words of `s` after lex and fold_digit_homophones, joined by spaces; with `glue`, a token
// glued to the next is marked "~".
static std::string folded(const char* s, bool glue = false) {
  auto t = lex(s);
  fold_digit_homophones(t);
  std::string words;
  for (const auto& tok : t)
    words += (words.empty() ? "" : " ") + tok.text + (glue && tok.glued ? "~" : "");
  return words;
}

TEST_CASE("digit homophones between digits are digits") {
  auto read = [](const char* s) { return folded(s); };
  CHECK(read("maintain two on zero knots") == "maintain two one zero knots");
  CHECK(read("speed two to zero") == "speed two two zero");
  CHECK(read("heading three three fine") == "heading three three five");
  CHECK(read("climb to two five zero") == "climb to two five zero");  // "to" before digits stays
  CHECK(read("two five zero for now") == "two five zero for now");    // "for" after digits stays
  CHECK(read("reduce speed to two once") == "reduce speed to two one");
  CHECK(read("Frontier one A four") == "frontier one eight four");
  CHECK(read("two once more") == "two once more");                    // only at the end
  CHECK(read("speed two zero to") == "speed two zero to");            // "to" never closes
  // noise between spoken digits: a lone lower-case letter, a hyphen-glued word
  CHECK(read("heading three f four zero") == "heading three four zero");
  CHECK(read("one nine-year zero knots") == "one nine zero knots");
  CHECK(read("six D four") == "six d four");                          // a written capital stays (a callsign letter)
  CHECK(read("runway two a") == "runway two a");                       // not between digits
  // thousands said as two words, one a homophone; a preposition first stays
  CHECK(read("maintain one to thousand") == "maintain one two thousand");
  CHECK(read("descend to won too thousand") == "descend to one two thousand");
  CHECK(read("climb won for thousand") == "climb one four thousand");
  CHECK(read("descend to four thousand") == "descend to four thousand");
  CHECK(read("climb for two thousand") == "climb for two thousand");
  CHECK(read("reduce speed to too fifty") == "reduce speed to two fifty");
  CHECK(read("it is too late") == "it is too late");
  // "to" opening a position said after spoken digits stays "to" where "two" would put it past the
  // pole: before a hemisphere, or before a latitude and longitude with decimals and a comma between
  CHECK(read("ual nine to four zero point eight north") ==
        "ual nine to four zero point eight north");
  CHECK(read("three zero four one to four five decimal three, eight decimal nine") ==
        "three zero four one to four five decimal three , eight decimal nine");
  CHECK(read("three zero four one to four five decimal three") ==
        "three zero four one two four five decimal three");
}

TEST_CASE("a word joined by hyphens of number words only is those words apart") {
  auto read = [](const char* s) { return folded(s, true); };
  CHECK(read("GATE2 at forty-five point three north") == "gate2 at forty five point three north");
  CHECK(read("climb two four-fifty-one") == "climb two four fifty one");
  CHECK(read("frequency one-two-thousand") == "frequency one two thousand");
  CHECK(read("heading thirty-three-oh-two") == "heading thirty three zero two");
  CHECK(read("squawk six-o-seven") == "squawk six zero seven");
  CHECK(read("level two-four-zero") == "level two four zero");
  CHECK(read("one-double-zero") == "one double zero");
  CHECK(read("two-two-oh") == "two two zero");           // closing too
  CHECK(read("oh-two") == "oh two");                     // not after a part
  CHECK(read("one nine-year zero") == "one nine zero");  // another part: the word is noise
  CHECK(read("one-way street") == "one way~ street");    // not between digits: kept, glued
  auto t = lex("forty-five point three");
  fold_digit_homophones(t);
  auto n = read_number(t, 0);
  REQUIRE(n.has_value());
  CHECK(n->value == doctest::Approx(45.3));
}

TEST_CASE("a speed said after thousand is a value of its own") {
  auto t = lex("one zero thousand two hundred and fifty knots");
  auto n = read_number(t, 0);
  REQUIRE(n.has_value());
  CHECK(n->value == 10000);
  auto speed = read_number(t, n->end);
  REQUIRE(speed.has_value());
  CHECK(speed->value == 250);
  CHECK(num("four thousand two hundred and fifty feet").value == 4250);
}

TEST_CASE("hyphen-joined digit groups are one number; aircraft models stay names") {
  auto t = lex("speed 21-0 for 91-48");
  REQUIRE(t.size() == 4);
  CHECK(t[1].kind == TokKind::kNumber);
  CHECK(t[1].num == 210);
  CHECK(t[3].num == 9148);
  for (const char* model : {"787-9", "737-800", "1-2-3-4-5"}) {
    auto m = lex(model);
    REQUIRE(m.size() == 1);
    CHECK_MESSAGE(m[0].kind == TokKind::kWord, model);
  }
}
