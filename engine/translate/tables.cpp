#include "translate/tables.h"

#include <algorithm>

#include "core/text.h"

namespace squawk::translate {

Tables::Tables(std::vector<Airline> airlines, std::vector<TypeName> types, std::vector<std::string> designators,
               std::vector<std::pair<std::string, char>> phonetic, Vocabulary vocabulary)
    : airlines_(std::move(airlines)),
      types_(std::move(types)),
      phonetic_(std::move(phonetic)),
      vocabulary_(std::move(vocabulary)) {
  for (auto& a : airlines_) a.telephony = text::lower(a.telephony);
  for (auto& t : types_) t.maker = text::lower(t.maker), t.model = text::lower(t.model);
  for (const auto& t : types_) designators_.push_back(text::upper(t.icao));
  for (const auto& d : designators) designators_.push_back(text::upper(d));
  std::sort(designators_.begin(), designators_.end());
  designators_.erase(std::unique(designators_.begin(), designators_.end()), designators_.end());
  for (const auto& a : airlines_) max_words_ = std::max(max_words_, text::split_ws(a.telephony).size());
  for (size_t i = 0; i < airlines_.size(); ++i) telephony_index_.emplace(airlines_[i].telephony, i);
  for (const auto& t : types_)
    if (!t.maker.empty()) makers_.insert(t.maker);
}

std::optional<std::string> Tables::airline_by_telephony(std::string_view phrase) const {
  const auto it = telephony_index_.find(text::lower(phrase));
  if (it == telephony_index_.end()) return std::nullopt;
  return airlines_[it->second].icao;
}

std::vector<std::string> Tables::telephony_of(std::string_view icao) const {
  std::vector<std::string> out;
  for (const auto& a : airlines_)
    if (text::iequals(icao, a.icao)) out.push_back(a.telephony);
  return out;
}

bool Tables::is_manufacturer(std::string_view word) const {
  return makers_.count(text::lower(word)) > 0;
}

std::optional<std::string> Tables::aircraft_type(std::string_view manufacturer, std::string_view model) const {
  const std::string maker = text::lower(manufacturer), m = text::lower(model);
  if (m.empty()) return std::nullopt;
  for (const auto& t : types_)
    if (m == t.model && (maker.empty() || maker == t.maker)) return t.icao;
  // "a380" written without the maker's letter after "airbus": "airbus 380".
  if (maker == "airbus" && m.front() != 'a') return aircraft_type("airbus", std::string("a").append(m));
  if (is_type_designator(m)) return text::upper(m);
  return std::nullopt;
}

bool Tables::is_type_designator(std::string_view s) const {
  return std::binary_search(designators_.begin(), designators_.end(), text::upper(s));
}

char Tables::phonetic_letter(std::string_view word) const {
  for (const auto& [w, letter] : phonetic_)
    if (word == w) return letter;
  return 0;
}

}  // namespace squawk::translate
