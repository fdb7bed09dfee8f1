#include "translate/tables.h"

#include <algorithm>

#include "core/text.h"

namespace squawk::translate {
namespace {

struct TypeEntry {
  const char* maker;  // lower case
  const char* model;  // lower case as usually written
  const char* icao;
};

// Model names as people write them; the first entry of a model wins.
const std::vector<TypeEntry>& type_entries() {
  static const std::vector<TypeEntry> kTypes = {
      {"boeing", "737", "B737"},         {"boeing", "737-700", "B737"},     {"boeing", "737-800", "B738"},
      {"boeing", "737-900", "B739"},     {"boeing", "737-900er", "B739"},   {"boeing", "737-600", "B736"},
      {"boeing", "737-300", "B733"},     {"boeing", "737-400", "B734"},     {"boeing", "737-500", "B735"},
      {"boeing", "737max", "B38M"},      {"boeing", "737-8", "B38M"},       {"boeing", "737-9", "B39M"},
      {"boeing", "747", "B744"},         {"boeing", "747-400", "B744"},     {"boeing", "747-8", "B748"},
      {"boeing", "757", "B752"},         {"boeing", "757-200", "B752"},     {"boeing", "757-300", "B753"},
      {"boeing", "767", "B763"},         {"boeing", "767-200", "B762"},     {"boeing", "767-300", "B763"},
      {"boeing", "767-400", "B764"},     {"boeing", "777", "B777"},         {"boeing", "777-200", "B772"},
      {"boeing", "777-200er", "B772"},   {"boeing", "777-300", "B773"},     {"boeing", "777-300er", "B77W"},
      {"boeing", "777-200lr", "B77L"},   {"boeing", "787", "B788"},         {"boeing", "787-8", "B788"},
      {"boeing", "787-9", "B789"},       {"boeing", "787-10", "B78X"},      {"boeing", "717", "B712"},
      {"boeing", "727", "B722"},         {"airbus", "a318", "A318"},        {"airbus", "a319", "A319"},
      {"airbus", "a320", "A320"},        {"airbus", "a321", "A321"},        {"airbus", "a319neo", "A19N"},
      {"airbus", "a320neo", "A20N"},     {"airbus", "a321neo", "A21N"},     {"airbus", "a300", "A306"},
      {"airbus", "a310", "A310"},        {"airbus", "a330", "A333"},        {"airbus", "a330-200", "A332"},
      {"airbus", "a330-300", "A333"},    {"airbus", "a330-900", "A339"},    {"airbus", "a340", "A343"},
      {"airbus", "a340-300", "A343"},    {"airbus", "a340-600", "A346"},    {"airbus", "a350", "A359"},
      {"airbus", "a350-900", "A359"},    {"airbus", "a350-1000", "A35K"},   {"airbus", "a380", "A388"},
      {"airbus", "a380-800", "A388"},    {"airbus", "a220-100", "BCS1"},    {"airbus", "a220-300", "BCS3"},
      {"airbus", "a220", "BCS3"},        {"embraer", "170", "E170"},        {"embraer", "175", "E175"},
      {"embraer", "190", "E190"},        {"embraer", "195", "E195"},        {"embraer", "e170", "E170"},
      {"embraer", "e175", "E175"},       {"embraer", "e190", "E190"},       {"embraer", "e195", "E195"},
      {"embraer", "145", "E145"},        {"embraer", "erj145", "E145"},     {"cessna", "172", "C172"},
      {"cessna", "152", "C152"},         {"cessna", "182", "C182"},         {"cessna", "208", "C208"},
      {"bombardier", "crj200", "CRJ2"},  {"bombardier", "crj700", "CRJ7"},  {"bombardier", "crj900", "CRJ9"},
      {"bombardier", "crj1000", "CRJX"}, {"bombardier", "q400", "DH8D"},    {"dash", "8", "DH8D"},
      {"atr", "72", "AT76"},             {"atr", "72-600", "AT76"},         {"atr", "42", "AT45"},
      {"fokker", "100", "F100"},         {"fokker", "70", "F70"},           {"fokker", "50", "F50"},
      {"mcdonnell", "md-11", "MD11"},    {"mcdonnell", "md-80", "MD80"},    {"concorde", "", "CONC"},
  };
  return kTypes;
}

const std::vector<std::string>& designators() {
  static const std::vector<std::string> kExtra = [] {
    std::vector<std::string> v;
    for (const auto& e : type_entries()) v.emplace_back(e.icao);
    for (const char* s : {"B38M", "B39M", "B3XM", "A20N", "A21N", "B77W", "B77L", "B78X", "A35K", "A388",
                          "C172", "C25A", "C560", "GLF4", "GLF5", "GLEX", "PC12", "BE20", "B350", "SR22",
                          "E290", "E75L", "E75S", "A400", "C130", "B748", "B744", "MD11", "DC10"})
      v.emplace_back(s);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  }();
  return kExtra;
}

}  // namespace

const std::vector<Airline>& airlines() {
  static const std::vector<Airline> kAirlines = {
      {"speedbird", "BAW"},              {"lufthansa", "DLH"},        {"klm", "KLM"},
      {"air france", "AFR"},     {"airfrans", "AFR"},       {"shamrock", "EIN"},         {"ryanair", "RYR"},
      {"easy", "EZY"},           {"easyjet", "EZY"},        {"alpine", "EZS"},           {"scandinavian", "SAS"},
      {"swiss", "SWR"},          {"austrian", "AUA"},       {"finnair", "FIN"},          {"emirates", "UAE"},
      {"qantas", "QFA"},         {"iberia", "IBE"},         {"alitalia", "AZA"},         {"tap", "TAP"},
      {"air portugal", "TAP"},   {"brussels", "BEL"},       {"beeline", "BEL"},          {"transavia", "TRA"},
      {"eurowings", "EWG"},      {"condor", "CFG"},         {"turkish", "THY"},
      {"virgin", "VIR"},         {"norshuttle", "NAX"},     {"wizz air", "WZZ"},         {"aeroflot", "AFL"},
      {"skytravel", "SKT"},      {"qatari", "QTR"},         {"etihad", "ETD"},
      {"singapore", "SIA"},      {"cathay", "CPA"},         {"japanair", "JAL"},         {"japan air", "JAL"},
      {"all nippon", "ANA"},     {"korean air", "KAL"},     {"asiana", "AAR"},           {"air china", "CCA"},
      {"china eastern", "CES"},  {"china southern", "CSN"}, {"hainan", "CHH"},           {"dynasty", "CAL"},
      {"eva", "EVA"},            {"air india", "AIC"},      {"springbok", "SAA"},        {"ethiopian", "ETH"},
      {"kenya", "KQA"},          {"egyptair", "MSR"},       {"el al", "ELY"},            {"saudia", "SVA"},
      {"new zealand", "ANZ"},    {"american", "AAL"},       {"united", "UAL"},           {"delta", "DAL"},
      {"southwest", "SWA"},      {"jetblue", "JBU"},        {"jet blue", "JBU"},         {"alaska", "ASA"},
      {"spirit wings", "NKS"},   {"frontier flight", "FFT"}, {"frontier", "FFT"},        {"envoy", "ENY"},
      {"endeavor", "EDV"},       {"endeavour", "EDV"},      {"brickyard", "RPA"},        {"skywest", "SKW"},
      {"piedmont", "PDT"},       {"blue streak", "JIA"},    {"lindbergh", "GJS"},        {"air wisconsin", "AWI"},
      {"horizon", "QXE"},        {"horizon air", "QXE"},    {"allegiant", "AAY"},        {"hawaiian", "HAL"},
      {"sun country", "SCX"},    {"sunwing", "SWG"},        {"westjet", "WJA"},          {"air canada", "ACA"},
      {"jazz", "JZA"},           {"transat", "TSC"},        {"rouge", "ROU"},            {"porter", "POE"},
      {"aeromexico", "AMX"},     {"volaris", "VOI"},        {"avianca", "AVA"},          {"copa", "CMP"},
      {"lan", "LAN"},            {"lan chile", "LAN"},      {"tam", "TAM"},              {"gol transporte", "GLO"},
      {"caribbean airlines", "BWA"}, {"caribbean", "BWA"},  {"fedex", "FDX"},            {"ups", "UPS"},
      {"giant", "GTI"},          {"abex", "ABX"},           {"cargolux", "CLX"},         {"execjet", "EJA"},
      {"exec jet", "EJA"},       {"flexjet", "LXJ"},        {"air shuttle", "ASH"},      {"air transport", "ATN"},
      {"compass", "CPZ"},        {"citrus", "TCF"},         {"cactus", "AWE"},           {"fiji", "FJI"},
      {"gemini", "GXA"},         {"chronos", "CNS"},        {"jetcard", "DPJ"},          {"fraction", "NJE"},
      {"itarrow", "ITY"},        {"november", "N"},         {"cobalt", "FCB"},           {"jetset", "JSX"},
      {"aer lingus", "EIN"},     {"aero lloyd", "AEF"},     {"hapag lloyd", "HLF"},      {"germanwings", "GWI"},
      {"transwede", "TWE"},      {"crossair", "CRX"},       {"swissair", "SWR"},         {"sabena", "SAB"},
      {"lauda", "LDA"},          {"tyrolean", "TYR"},       {"britannia", "BAL"},        {"air berlin", "BER"},
      {"malev", "MAH"},          {"pollot", "LOT"},         {"czech", "CSA"},            {"olympic", "OAL"},
      {"cyprus", "CYP"},         {"tarom", "ROT"},          {"luxair", "LGL"},           {"spanair", "JKK"},
      {"air europa", "AEA"},     {"vueling", "VLG"},        {"air malta", "AMC"},        {"adria", "ADR"},
      {"croatia", "CTN"},        {"aegean", "AEE"},         {"edelweiss", "EDW"},        {"air baltic", "BTI"},
      {"airbaltic", "BTI"},      {"iceair", "ICE"},         {"martinair", "MPH"},        {"corsair", "CRL"},
      {"air dolomiti", "DLA"},   {"dolomiti", "DLA"},       {"gulf air", "GFA"},         {"kuwaiti", "KAC"},
      {"cedar jet", "MEA"},      {"royal air maroc", "RAM"}, {"air algerie", "DAH"},     {"sunturk", "PGT"},
      {"sunexpress", "SXS"},     {"kestrel", "TCX"},        {"monarch", "MON"},          {"channex", "EXS"},
      {"aerosvit", "AEW"},       {"belavia", "BRU"},        {"estonian", "ELL"},         {"loganair", "LOG"},
      {"futura", "FUA"},         {"viva", "VIV"},
  };
  return kAirlines;
}

std::optional<std::string> airline_by_telephony(std::string_view phrase) {
  std::string p = text::lower(phrase);
  for (const auto& a : airlines())
    if (p == a.telephony) return std::string(a.icao);
  return std::nullopt;
}

std::vector<std::string> telephony_of(std::string_view icao) {
  std::vector<std::string> out;
  for (const auto& a : airlines())
    if (text::iequals(icao, a.icao)) out.emplace_back(a.telephony);
  return out;
}

size_t max_telephony_words() {
  static const size_t kMax = [] {
    size_t m = 1;
    for (const auto& a : airlines()) m = std::max(m, text::split_ws(a.telephony).size());
    return m;
  }();
  return kMax;
}

bool is_manufacturer(std::string_view word) {
  std::string w = text::lower(word);
  for (const auto& e : type_entries())
    if (w == e.maker) return true;
  return false;
}

std::optional<std::string> aircraft_type(std::string_view manufacturer, std::string_view model) {
  std::string maker = text::lower(manufacturer), m = text::lower(model);
  if (m.empty()) return std::nullopt;
  for (const auto& e : type_entries())
    if (m == e.model && (maker.empty() || maker == e.maker)) return std::string(e.icao);
  // "a380" written without the maker's letter after "airbus": "airbus 380".
  if (maker == "airbus" && !m.empty() && m.front() != 'a') return aircraft_type("airbus", std::string("a").append(m));
  if (is_type_designator(m)) return text::upper(m);
  return std::nullopt;
}

bool is_type_designator(std::string_view s) {
  std::string u = text::upper(s);
  return std::binary_search(designators().begin(), designators().end(), u);
}

}  // namespace squawk::translate
