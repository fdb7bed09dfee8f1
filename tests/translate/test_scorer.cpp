// Corpus scoring rules (shared/corpora/README.md) and the evaluator.
#include <doctest/doctest.h>

#include "translate/corpus.h"
#include "translate/scorer.h"

using namespace squawk::translate;

TEST_CASE("aliases fold and names ignore case") {
  CHECK(canonical_command("turn") == "HDG");
  CHECK(canonical_command("Heading") == "HDG");
  CHECK(canonical_command("create") == "CRE");
  CHECK(canonical_command("dct") == "DIRECT");
  CHECK(canonical_command("pause") == "HOLD");
  CHECK(canonical_command("asas") == "CDMETHOD");  // the registry's canonical name
  CHECK(same_command("heading klm123 90", "HDG KLM123 090"));
  CHECK_FALSE(same_command("HDG KLM123 90", "HDG KLM124 90"));
}

TEST_CASE("altitudes compare in feet within 50 ft") {
  CHECK(same_command("ALT KL1 FL300", "ALT KL1 30000"));
  CHECK(same_command("ALT KL1 30040", "ALT KL1 FL300"));
  CHECK_FALSE(same_command("ALT KL1 30060", "ALT KL1 FL300"));
  CHECK(same_command("ALT KL1 FL90", "ALT KL1 9000"));
}

TEST_CASE("RMETHV: ON and V/S both mean vertical resolutions on, OFF and NONE off") {
  CHECK(same_command("RMETHV V/S", "RMETHV ON"));
  CHECK(same_command("ASAS STATEBASED", "ASAS ON"));
  CHECK(same_command("CDMETHOD STATEBASED", "ASAS ON"));
  CHECK_FALSE(same_command("ASAS STATEBASED", "ASAS OFF"));
  CHECK(same_command("RMETHV NONE", "RMETHV OFF"));
  CHECK_FALSE(same_command("RMETHV V/S", "RMETHV OFF"));
}

TEST_CASE("speeds: knots or Mach, never mixed") {
  CHECK(same_command("SPD KL1 M0.78", "SPD KL1 .78"));
  CHECK(same_command("SPD KL1 0.78", "SPD KL1 M0.78"));
  CHECK_FALSE(same_command("SPD KL1 250", "SPD KL1 M0.78"));
  CHECK_FALSE(same_command("SPD KL1 251", "SPD KL1 250"));
}

TEST_CASE("headings modulo 360, positions within 1e-3 degree") {
  CHECK(same_command("HDG KL1 360", "HDG KL1 0"));
  CHECK(same_command("HDG KL1 359.7", "HDG KL1 0"));
  CHECK_FALSE(same_command("HDG KL1 358", "HDG KL1 0"));
  CHECK(same_command("DEFWPT X 51.5 -0.1167", "DEFWPT X 51.5 -0.116667"));
  CHECK_FALSE(same_command("DEFWPT X 51.5 -0.118", "DEFWPT X 51.5 -0.116667"));
  CHECK(same_command("CRE A B738 52 4 90 FL250 280", "CRE A B738 52.0 4.0 090 25000 280"));
}

TEST_CASE("HDG turn direction: L and R fold to LEFT and RIGHT; an expected line without one accepts any") {
  CHECK(same_command("HDG KL1 300 RIGHT", "HDG KL1 300 R"));
  CHECK(same_command("HDG KL1 20 l", "HDG KL1 020 LEFT"));
  CHECK_FALSE(same_command("HDG KL1 300 LEFT", "HDG KL1 300 RIGHT"));
  CHECK_FALSE(same_command("HDG KL1 300", "HDG KL1 300 RIGHT"));
  CHECK(same_command("HDG KL1 300 RIGHT", "HDG KL1 300"));
  CHECK_FALSE(same_command("HDG KL1 310 RIGHT", "HDG KL1 300"));
}

TEST_CASE("ALT's vertical speed is a magnitude: its sign does not count") {
  CHECK(same_command("ALT KL1 FL100 2000", "ALT KL1 FL100 -2000"));
  CHECK_FALSE(same_command("ALT KL1 FL100 1500", "ALT KL1 FL100 -2000"));
}

TEST_CASE("AT's constraint compares as an altitude or a speed") {
  CHECK(same_command("AT SWR18L KLO alt FL80", "AT SWR18L KLO ALT FL080"));
  CHECK(same_command("AT SWR18L KLO ALT 8000", "AT SWR18L KLO ALT FL080"));
  CHECK(same_command("AT SWR18L KLO SPD 250", "AT SWR18L KLO SPD 250"));
  CHECK_FALSE(same_command("AT SWR18L KLO ALT FL90", "AT SWR18L KLO ALT FL080"));
  // every altitude argument the registry declares: FL080 = FL80 = 8000 ft, by the argument's place
  CHECK(same_command("MOVE JAF3KM BUB FL080 250", "MOVE JAF3KM BUB FL80 250"));
  CHECK(same_command("MOVE JAF3KM 52.1 4.2 FL080 250", "MOVE JAF3KM 52.1 4.2 8000 250"));
  CHECK_FALSE(same_command("MOVE JAF3KM BUB FL090 250", "MOVE JAF3KM BUB FL80 250"));
  CHECK_FALSE(same_command("MOVE JAF3KM BUB FL080 250", "MOVE JAF3KM SPY FL80 250"));
  CHECK(same_command("ATALT KL1 FL080 SPD KL1 250", "ATALT KL1 FL80 SPD KL1 250"));
  CHECK_FALSE(same_command("AT SWR18L KLO SPD 250", "AT SWR18L KLO ALT 250"));
}

TEST_CASE("ALT then VS (or VS then ALT) of one aircraft is ALT with that vertical speed") {
  CHECK(score_case("ALT BAW1 FL100 ; VS BAW1 -1500", false, "ALT BAW1 FL100 1500"));
  CHECK(score_case("VS BAW1 -1500 ; ALT BAW1 FL100", false, "ALT BAW1 FL100 -1500"));
  CHECK(score_case("ALT BAW1 FL100 1500", false, "ALT BAW1 FL100 ; VS BAW1 -1500"));
  CHECK(score_case("HDG BAW1 90 ; ALT BAW1 FL100 ; VS BAW1 -1500", false,
                   "HDG BAW1 90 ; ALT BAW1 FL100 1500"));
  CHECK_FALSE(score_case("ALT BAW1 FL100 ; VS BAW1 -1500", false, "ALT BAW1 FL100 2000"));
  // a vertical speed within 1 ft/min (8 m/s down is -1574.8 ft/min), with its sign
  CHECK(score_case("VS BAW1 -1575", false, "VS BAW1 -1574.8"));
  CHECK(score_case("ALT BAW1 FL100 1575", false, "ALT BAW1 FL100 -1574.8"));
  CHECK_FALSE(score_case("VS BAW1 -1572", false, "VS BAW1 -1574.8"));
  CHECK_FALSE(score_case("VS BAW1 1575", false, "VS BAW1 -1574.8"));
  CHECK_FALSE(score_case("ALT BAW1 FL100 ; VS KLM2 -1500", false, "ALT BAW1 FL100 1500"));
  CHECK_FALSE(score_case("ALT BAW1 FL100 1000 ; VS BAW1 -1500", false, "ALT BAW1 FL100 1500"));
}

TEST_CASE("LNAV ON right after a direct-to of the same aircraft adds nothing") {
  CHECK(score_case("DIRECT JBU614 BETTE ; LNAV JBU614 ON", false, "DIRECT JBU614 BETTE"));
  CHECK_FALSE(score_case("DIRECT JBU614 BETTE ; LNAV JBU614 OFF", false, "DIRECT JBU614 BETTE"));
  CHECK_FALSE(score_case("DIRECT JBU614 BETTE ; LNAV UAL9 ON", false, "DIRECT JBU614 BETTE"));
}

TEST_CASE("a time compares in seconds as the simulator reads it: MM:SS and HH:MM:SS") {
  CHECK(score_case("FF 1:30", false, "FF 90"));
  CHECK(score_case("FF 90", false, "FF 0:01:30"));
  CHECK_FALSE(score_case("FF 1:30", false, "FF 130"));
  CHECK(score_case("SCHEDULE 1200 HOLD", false, "SCHEDULE 00:20:00 HOLD"));
  CHECK_FALSE(score_case("SCHEDULE 1200 HOLD", false, "SCHEDULE 00:20:00 OP"));
}

TEST_CASE("DELAY and SCHEDULE compare the command they run as a command: FL070 is FL70") {
  CHECK(score_case("DELAY 120 ALT EZS1485 FL70", false, "DELAY 0:02:00 ALT EZS1485 FL070"));
  CHECK(score_case("SCHEDULE 600 SPD KLM1 250", false, "SCHEDULE 00:10:00 SPD KLM1 250.2"));
  CHECK_FALSE(score_case("DELAY 120 ALT EZS1485 FL80", false, "DELAY 120 ALT EZS1485 FL070"));
  CHECK_FALSE(score_case("DELAY 120 ALT KLM1 FL70", false, "DELAY 120 ALT EZS1485 FL70"));
  CHECK_FALSE(score_case("DELAY 60 ALT EZS1485 FL70", false, "DELAY 120 ALT EZS1485 FL70"));
}

TEST_CASE(
    "AT acid wp alt/spd is the ALT and the SPD constraint at that waypoint, in either order") {
  CHECK(score_case("AT GFA272 MAKIN ALT FL100 ; AT GFA272 MAKIN SPD 250", false,
                   "AT GFA272 MAKIN FL100/250"));
  CHECK(score_case("AT GFA272 MAKIN SPD 250 ; AT GFA272 MAKIN ALT FL100", false,
                   "GFA272 AT MAKIN 10000/250"));
  CHECK(score_case("AT GFA272 MAKIN SPD 250", false, "AT GFA272 MAKIN /250"));
  CHECK_FALSE(
      score_case("AT GFA272 MAKIN ALT FL100 ; SPD GFA272 250", false, "AT GFA272 MAKIN FL100/250"));
  CHECK_FALSE(score_case("AT GFA272 MAKIN ALT FL100 ; AT GFA272 ADSIS SPD 250", false,
                         "AT GFA272 MAKIN FL100/250"));
  CHECK_FALSE(score_case("AT GFA272 MAKIN ALT FL110 ; AT GFA272 MAKIN SPD 250", false,
                         "AT GFA272 MAKIN FL100/250"));
  CHECK_FALSE(score_case("AT GFA272 MAKIN ALT FL100", false, "AT GFA272 MAKIN FL100/250"));
}

TEST_CASE("AFTER / BEFORE acid wp ADDWPT new equal ADDWPT's afterwp / beforewp") {
  CHECK(score_case("ADDWPT DLH4AX IVLUT,,,ARTIP", false, "AFTER DLH4AX ARTIP ADDWPT IVLUT"));
  CHECK(score_case("ADDWPT DLH4AX NYKER,,,,ANDIK", false, "DLH4AX BEFORE ANDIK ADDWPT NYKER"));
  CHECK(score_case("ADDWPT KL204 SSB,FL100,,SPL", false, "KL204 AFTER SPL ADDWPT SSB FL100"));
  CHECK_FALSE(score_case("ADDWPT DLH4AX IVLUT,,,ARTIP", false, "BEFORE DLH4AX ARTIP ADDWPT IVLUT"));
  CHECK_FALSE(score_case("ADDWPT DLH4AX IVLUT", false, "AFTER DLH4AX ARTIP ADDWPT IVLUT"));
}

TEST_CASE("BlueSky's callsign-first form equals the command-first one, nested too") {
  CHECK(same_command("KL1 SPD 250", "SPD KL1 250"));
  CHECK(same_command("ATALT KL1 FL130 SPD KL1 250", "ATALT KL1 FL130 KL1 SPD 250"));
  CHECK_FALSE(same_command("ATALT KL1 FL130 SPD KL1 250", "ATALT KL1 FL130 KL1 SPD 260"));
}

TEST_CASE("conditionals compare the condition and the nested command") {
  CHECK(same_command("ATALT AC01 20000 SPD AC01 280", "ATALT AC01 FL200 SPD AC01 280"));
  CHECK_FALSE(same_command("ATALT AC01 20000 SPD AC01 290", "ATALT AC01 FL200 SPD AC01 280"));
  CHECK(same_command("ECHO hello World", "ECHO Hello world"));
  CHECK(same_command("ATDIST KL1 OKE 20 ALT KL1 FL80", "ATDIST KL1 OKE 20 ALT KL1 FL080"));
  CHECK(same_command("ATDIST KL1 OKE 20.0 ALT KL1 8000", "ATDIST KL1 OKE 20 KL1 ALT FL080"));
  CHECK_FALSE(same_command("ATDIST KL1 OKE 25 ALT KL1 FL80", "ATDIST KL1 OKE 20 ALT KL1 FL80"));
  CHECK_FALSE(same_command("ATDIST KL1 OKE 20 ALT KL1 FL90", "ATDIST KL1 OKE 20 ALT KL1 FL80"));
  CHECK_FALSE(same_command("ATDIST KL1 SPY 20 ALT KL1 FL80", "ATDIST KL1 OKE 20 ALT KL1 FL80"));
  // AT acid wpt DO (or STACK) command: the waypoint, then the stored command
  CHECK(same_command("AT KL1 OKE DO ALT KL1 FL80", "AT KL1 OKE DO ALT KL1 FL080"));
  CHECK(same_command("KL1 AT OKE STACK KL1 ALT 8000", "AT KL1 OKE DO ALT KL1 FL080"));
  CHECK_FALSE(same_command("AT KL1 OKE DO ALT KL1 FL90", "AT KL1 OKE DO ALT KL1 FL80"));
  CHECK_FALSE(same_command("AT KL1 SPY DO ALT KL1 FL80", "AT KL1 OKE DO ALT KL1 FL80"));
  CHECK_FALSE(same_command("AT KL1 OKE ALT FL80",
                           "AT KL1 OKE DO ALT KL1 FL80"));  // a constraint is not a command
}

TEST_CASE("arguments left out between commas keep their places; a comma at a word's end only separates") {
  CHECK(same_command("ADDWPT KL1 SPY,,,ARTIP", "ADDWPT KL1 SPY,,,ARTIP"));
  CHECK_FALSE(same_command("ADDWPT KL1 SPY,,,ARTIP", "ADDWPT KL1 SPY,,,,ARTIP"));  // after, not before
  CHECK_FALSE(same_command("ADDWPT KL1 SPY ARTIP", "ADDWPT KL1 SPY,,,ARTIP"));
  CHECK_FALSE(same_command("ADDWPT KL1 52.1 4.3,,280", "ADDWPT KL1 52.1 4.3,280"));  // a speed, not an altitude
  CHECK(same_command("ALT KL1, FL100", "ALT KL1 FL100"));
  CHECK(same_command("ALT KL1 FL100,", "ALT KL1 FL100"));
}

TEST_CASE("CRE at a named place compares heading, altitude and speed as such") {
  CHECK(same_command("CRE KL1 A320 SPY 270 FL90 240", "CRE KL1 A320 SPY 270 FL090 240"));
  CHECK_FALSE(same_command("CRE KL1 A320 SPY 270 FL90 240", "CRE KL1 A320 SPY 270 FL100 240"));
}

TEST_CASE("lists, alternatives and ASK") {
  CHECK(score_case("DEL AC02 ; DEL AC01", false, "DEL AC01 ; DEL AC02 || DEL AC02 ; DEL AC01"));
  CHECK_FALSE(score_case("DEL AC01", false, "DEL AC01 ; DEL AC02"));
  CHECK(score_case("", true, "ASK"));
  CHECK_FALSE(score_case("ALT AC01 FL100", false, "ASK"));
  CHECK_FALSE(score_case("ALT AC01 FL100", true, "ALT AC01 FL100"));
  CHECK(split_commands(" A ; ; B ") == std::vector<std::string>{"A", "B"});
}

TEST_CASE("corpus reading and right / asked / wrong per category") {
  const std::string tsv =
      "id\tsetup\tutterance\texpected\tcategory\n"
      "a1\t\tClimb AC01 by 2000 feet\tALT AC01 27000\trelative\n"
      "a2\t\tChange the speed\tASK\task\n"
      "a3\t\tPause the simulation\tHOLD\tsim\n"
      "a4\t\tDelete AC01\tDEL AC01\tdelete\n"
      "a5\t\tClimb\tASK\task\n";
  auto cases = parse_corpus(tsv, "mem");
  REQUIRE(cases.is_ok());
  REQUIRE(cases->size() == 5);
  // A stand-in translator: right, asked (a question where a command was
  // expected), wrong (another command), a question where ASK was expected,
  // and a command where a question was expected (wrong).
  auto fake = [](const CorpusCase& c) -> squawk::Result<Translation> {
    Translation t;
    if (c.id == "a1") t.commands = {"ALT AC01 27000"};
    if (c.id == "a2") t.ask = "Which aircraft?";
    if (c.id == "a3") t.ask = "Pause what?";
    if (c.id == "a4") t.error = "rejected";
    if (c.id == "a5") t.commands = {"ALT AC01 FL100"};
    return t;
  };
  auto r = evaluate(*cases, fake);
  CHECK(r.cases == 5);
  CHECK(r.correct == 2);
  CHECK(r.asked == 2);
  CHECK(r.wrong == 1);
  REQUIRE(r.categories.size() == 4);
  CHECK(r.categories[1].category == "ask");
  CHECK(r.categories[1].correct == 1);
  CHECK(r.categories[1].wrong == 1);
  CHECK(r.categories[2].asked == 1);
  CHECK(format_report(r, "t").find("wrong") != std::string::npos);
  auto bad = parse_corpus("id\tsetup\tutterance\texpected\tcategory\nonly\ttwo\n", "mem");
  CHECK_FALSE(bad.is_ok());
  CHECK(bad.status().message().find("mem:2") != std::string::npos);
  auto err = evaluate({{"b1", "CRE", "Delete it", "DEL X", "delete"}},
                      [](const CorpusCase&) -> squawk::Result<Translation> { return squawk::Status::invalid("setup failed"); });
  CHECK(err.correct == 0);
  CHECK(err.asked == 1);
  CHECK(err.outcomes[0].produced.rfind("error:", 0) == 0);
}

TEST_CASE("a yes/no question before destructive commands: right when a question or those commands were expected") {
  const std::vector<CorpusCase> cases = {{"c1", "", "delete everything", "ASK", "ask"},
                                         {"c2", "", "delete both", "DEL A ; DEL B", "delete"},
                                         {"c3", "", "delete the Lufthansas", "DEL A ; DEL C", "delete"}};
  auto r = evaluate(cases, [](const CorpusCase&) -> squawk::Result<Translation> {
    Translation t;
    t.ask = "Delete 2 aircraft (A, B)? (yes or no)";
    t.on_yes = {"DEL A", "DEL B"};
    return t;
  });
  CHECK(r.correct == 2);
  CHECK(r.asked == 0);
  CHECK(r.wrong == 1);  // the question proposes other aircraft than the request named
  CHECK(r.outcomes[2].produced.find("[yes runs: DEL A ; DEL B]") != std::string::npos);
}

TEST_CASE(
    "a request of only what squawk does not simulate: no command, the note shown, scored as no "
    "command") {
  const std::vector<CorpusCase> cases = {
      {"n1", "", "KLM12 hold at SUGOL", "ASK", "ask"},
      {"n2", "", "KLM12 squawk 1234", "SQUAWK KLM12 1234", "other"}};
  auto r = evaluate(cases, [](const CorpusCase&) -> squawk::Result<Translation> {
    Translation t;
    t.note = "squawk does not simulate holding patterns ('hold'): nothing was sent for that.";
    return t;
  });
  CHECK(r.correct == 1);
  CHECK(r.asked == 1);
  CHECK(r.outcomes[0].produced ==
        "squawk does not simulate holding patterns ('hold'): nothing was sent for that.");
  Translation issued;
  issued.commands = {"ALT KLM12 FL300"};
  issued.note = "squawk does not simulate holding patterns ('hold'): nothing was sent for that.";
  CHECK(issued.text() == "ALT KLM12 FL300");
}

TEST_CASE(
    "a waypoint added after the one its route ends with after the setup is the plain ADDWPT") {
  const char* setup =
      "CRE RZO221 A321 38 -25 075 FL340 270 ; ADDWPT RZO221 NOVPA ; ADDWPT RZO221 ETIRA";
  CHECK(score_case("ADDWPT RZO221 39 -15,,,ETIRA", false, "ADDWPT RZO221 39 -15", setup));
  CHECK(score_case("ADDWPT RZO221 DAVOS", false, "AFTER RZO221 ETIRA ADDWPT DAVOS", setup));
  CHECK(score_case("ADDWPT RZO221 DAVOS,FL300,,ETIRA", false, "ADDWPT RZO221 DAVOS FL300", setup));
  // (after a waypoint before the end, before the end, another aircraft's, or with no setup: another
  // route)
  CHECK_FALSE(score_case("ADDWPT RZO221 39 -15,,,NOVPA", false, "ADDWPT RZO221 39 -15", setup));
  CHECK_FALSE(score_case("ADDWPT RZO221 39 -15,,,,ETIRA", false, "ADDWPT RZO221 39 -15", setup));
  CHECK_FALSE(score_case("ADDWPT RZO221 39 -15,,,ETIRA", false, "ADDWPT RZO221 39 -15"));
  // (the end as ADDWPT lines after an afterwp or before a beforewp, a DELRTE and a DEST leave it)
  CHECK(score_case("ADDWPT KL1 C,,,B", false, "ADDWPT KL1 C",
                   "ADDWPT KL1 A ; ADDWPT KL1 B,,,A ; DEST KL1 EHAM"));
  CHECK_FALSE(score_case("ADDWPT KL1 C,,,B", false, "ADDWPT KL1 C",
                         "ADDWPT KL1 A ; ADDWPT KL1 B ; DELRTE KL1"));
  CHECK(score_case("ADDWPT KL1 C,,,A", false, "ADDWPT KL1 C", "ADDWPT KL1 A ; ADDWPT KL1 B,,,,A"));
  CHECK_FALSE(
      score_case("ADDWPT KL1 C,,,B", false, "ADDWPT KL1 C", "ADDWPT KL1 A ; ADDWPT KL1 B,,,,A"));
}
