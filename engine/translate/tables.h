// Data tables of the offline translator: airline telephony designators and
// aircraft type names.
//
// Contract: lookups are case-insensitive and never fail; a miss is nullopt.
//  - airline_by_telephony(): a radio telephony word or phrase ("speedbird",
//    "air france", "jetblue") -> ICAO three-letter prefix ("BAW").
//  - telephony_of(): the reverse, for matching a spoken name to an aircraft id.
//  - aircraft_type(): a manufacturer (may be empty) and a model as written
//    ("boeing","737-800"; "","747-400"; "airbus","a380-800"; "","a320")
//    -> ICAO type designator ("B738", "B744", "A388", "A320").
//  - is_type_designator(): a known ICAO designator ("B738", "A20N").
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace squawk::translate {

struct Airline {
  const char* telephony;  // lower case, words separated by one space
  const char* icao;       // three-letter prefix ("N" for US registrations, "november")
};

const std::vector<Airline>& airlines();
std::optional<std::string> airline_by_telephony(std::string_view phrase);
// All telephony phrases of an ICAO prefix (empty when unknown).
std::vector<std::string> telephony_of(std::string_view icao);
// Longest telephony phrase, in words, of the table.
size_t max_telephony_words();

bool is_manufacturer(std::string_view word);
std::optional<std::string> aircraft_type(std::string_view manufacturer, std::string_view model);
bool is_type_designator(std::string_view s);

}  // namespace squawk::translate
