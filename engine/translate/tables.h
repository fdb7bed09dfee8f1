// The names the callsign and type matchers know: airline telephony
// designators, aircraft type names and designators, the phonetic alphabet,
// and the instruction vocabulary (vocabulary.h).
// The data lives in Lua (scripts/translate/names.lua and the phonetic
// alphabet of scripts/translate/lexicon.lua); the grammar hands it over once
// (squawk.translate.tables) and passes it with each utterance.
//
// Contract: lookups are case-insensitive and never fail; a miss is nullopt
// (0 for phonetic_letter).
//  - airline_by_telephony(): a radio telephony word or phrase ("speedbird",
//    "air france") -> ICAO prefix ("BAW"); telephony_of() the reverse.
//  - aircraft_type(): a manufacturer (may be empty) and a model as written
//    ("boeing","737-800"; "","747-400") -> ICAO designator ("B738", "B744").
//  - is_type_designator(): a known ICAO designator ("B738", "A20N").
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "translate/vocabulary.h"

namespace squawk::translate {

struct Airline {
  std::string telephony;  // lower case, words separated by one space
  std::string icao;       // prefix ("N" for US registrations, "november")
};

struct TypeName {
  std::string maker;  // lower case; may be empty
  std::string model;  // lower case as usually written
  std::string icao;
};

class Tables {
 public:
  Tables() = default;
  Tables(std::vector<Airline> airlines, std::vector<TypeName> types, std::vector<std::string> designators,
         std::vector<std::pair<std::string, char>> phonetic, Vocabulary vocabulary = {});

  std::optional<std::string> airline_by_telephony(std::string_view phrase) const;
  std::vector<std::string> telephony_of(std::string_view icao) const;
  size_t max_telephony_words() const { return max_words_; }
  bool is_manufacturer(std::string_view word) const;
  std::optional<std::string> aircraft_type(std::string_view manufacturer, std::string_view model) const;
  bool is_type_designator(std::string_view s) const;
  char phonetic_letter(std::string_view word) const;  // "alpha" -> 'A', or 0
  const Vocabulary& vocabulary() const { return vocabulary_; }

 private:
  std::vector<Airline> airlines_;
  std::vector<TypeName> types_;
  std::vector<std::string> designators_;  // upper case, sorted, unique
  std::vector<std::pair<std::string, char>> phonetic_;
  size_t max_words_ = 1;
  Vocabulary vocabulary_;
  // Indexes built once by the constructor, read by the lookups above:
  // telephony_index_ maps each lower-case telephony to the index in airlines_
  // of its first airline (the one a scan in order would find); makers_ holds
  // every non-empty lower-case maker of types_.
  std::unordered_map<std::string, size_t> telephony_index_;
  std::unordered_set<std::string> makers_;
};

}  // namespace squawk::translate
