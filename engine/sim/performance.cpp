#include "sim/performance.h"

#include <array>

#include "core/text.h"

namespace squawk::sim {

namespace {
// Table in performance.h: vmin, vmax, vsmin, vsmax, hmax, axmax.
constexpr std::array<PerfLimits, 4> kLimits = {{
    {50.0, 180.0, -25.0, 25.0, 12500.0, 0.5},   // jet
    {40.0, 130.0, -12.5, 12.5, 7600.0, 0.5},    // turboprop
    {25.0, 90.0, -5.0, 5.0, 4500.0, 0.5},       // piston
    {0.0, 80.0, -10.0, 10.0, 3000.0, 0.5},      // helicopter
}};

// Common ICAO designators of the non-jet classes.
constexpr std::string_view kTurboprops[] = {
    "AT43", "AT44", "AT45", "AT46", "AT72", "AT73", "AT75", "AT76", "ATP",  "B190", "B350",
    "BE20", "BE30", "BE9L", "C130", "C208", "D228", "D328", "DH8A", "DH8B", "DH8C", "DH8D",
    "DHC6", "E110", "E120", "F27",  "F50",  "JS31", "JS32", "JS41", "L410", "PC12", "SF34",
    "SW4",  "TBM7", "TBM8", "TBM9", "P180", "SB20", "AN26", "A400"};
constexpr std::string_view kPistons[] = {
    "C150", "C152", "C162", "C172", "C177", "C182", "C206", "C210", "P28A", "P28B", "P28R",
    "PA28", "PA32", "PA34", "PA44", "PA46", "SR20", "SR22", "DA40", "DA42", "DA20", "BE33",
    "BE35", "BE36", "BE55", "BE58", "M20P", "M20T", "DR40", "AA5",  "C310", "C340", "C421"};
constexpr std::string_view kHelicopters[] = {
    "A109", "A119", "A139", "A169", "A189", "AS32", "AS35", "AS50", "AS55", "AS65", "B06",
    "B407", "B412", "B429", "EC20", "EC30", "EC35", "EC45", "EC55", "EC75", "H125", "H130",
    "H135", "H145", "H160", "H175", "R22",  "R44",  "R66",  "S76",  "S92",  "NH90"};

template <size_t N>
bool listed(const std::string_view (&list)[N], std::string_view t) {
  for (std::string_view s : list)
    if (s == t) return true;
  return false;
}
}  // namespace

std::vector<std::pair<std::string_view, PerfClass>> class_model_types() {
  std::vector<std::pair<std::string_view, PerfClass>> out;
  for (auto t : kTurboprops) out.emplace_back(t, PerfClass::kTurboprop);
  for (auto t : kPistons) out.emplace_back(t, PerfClass::kPiston);
  for (auto t : kHelicopters) out.emplace_back(t, PerfClass::kHelicopter);
  return out;
}

PerfClass perf_class_of(std::string_view actype) {
  const std::string t = text::upper(text::trim(actype));
  if (listed(kTurboprops, t)) return PerfClass::kTurboprop;
  if (listed(kPistons, t)) return PerfClass::kPiston;
  if (listed(kHelicopters, t)) return PerfClass::kHelicopter;
  return PerfClass::kJet;
}

const char* perf_class_name(PerfClass c) {
  switch (c) {
    case PerfClass::kJet: return "jet";
    case PerfClass::kTurboprop: return "turboprop";
    case PerfClass::kPiston: return "piston";
    case PerfClass::kHelicopter: return "helicopter";
  }
  return "jet";
}

const PerfLimits& perf_limits(PerfClass c) { return kLimits[static_cast<size_t>(c)]; }

}  // namespace squawk::sim
