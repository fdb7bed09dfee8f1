// Performance model and wind commands: PERF, WIND, GETWIND.
#include <cmath>

#include "command/handler_util.h"
#include "core/text.h"
#include "core/units.h"
#include "sim/openap_data.h"

namespace squawk::command {

namespace {

std::string model_name(const sim::Simulation& s) {
  return s.openap() ? "PERF OPENAP " + s.openap()->dir() : std::string("PERF CLASS (squawk's four type classes)");
}

// PERF [OPENAP [dir] | CLASS | LEGACY | OFF]
Result<std::string> perf(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return model_name(s);
  const std::string& v = c[0].text;
  if (v == "OPENAP") {
    std::shared_ptr<const sim::OpenapData> data;
    if (c.has(1)) {
      const std::string dir(text::trim(c[1].text));
      SQUAWK_RETURN_IF_ERROR(c.stack.check_read_folder(dir, "argument 2: OpenAP folder"));
      SQUAWK_ASSIGN_OR_RETURN(data, sim::OpenapData::load(dir));
    } else {
      data = s.openap() ? s.openap() : sim::default_openap();
      if (!data)
        return Status::not_found(
            "argument 2: no OpenAP data folder known; give one (PERF OPENAP dir) or set SQUAWK_OPENAP");
    }
    s.set_openap(std::move(data));
    return std::string();
  }
  if (v == "CLASS" || v == "LEGACY" || v == "OFF") {
    s.set_openap(nullptr);
    return std::string();
  }
  return Status::invalid("argument 1: expected OPENAP [dir], CLASS or LEGACY, got " + text::quoted(v));
}

// A WIND altitude: a plain number is feet, an altitude (FL200) as BlueSky
// reads it (its metres taken as feet once more).
double wind_alt(const ArgValue& a) { return a.num * units::kFt; }

// WIND lat,lon,dir,spd | WIND lat,lon,alt,dir,spd,[alt,dir,spd,...] | WIND lat,lon,DEL
Result<std::string> wind(Call& c) {
  sim::Simulation& s = c.stack.sim();
  const GeoPoint p = c[0].pos;
  std::vector<const ArgValue*> data;
  for (size_t k = 1; k < c.args.size(); ++k)
    if (c[k].present) data.push_back(&c[k]);
  if (data.size() == 1 && data[0]->type == ArgType::kTxt && data[0]->text == "DEL") {
    s.clear_wind();
    return std::string();
  }
  for (size_t k = 0; k < data.size(); ++k)
    if (data[k]->type == ArgType::kTxt)
      return Status::invalid("argument " + std::to_string(k + 3) + ": expected a number, got " +
                             text::quoted(data[k]->text));
  if (data.size() == 2) {
    SQUAWK_RETURN_IF_ERROR(s.add_wind_uniform(p.lat, p.lon, data[0]->num, units::kt_to_ms(data[1]->num)));
    return std::string();
  }
  if (data.size() < 3 || data.size() % 3 != 0)
    return Status::invalid("expected dir,spd or altitude,dir,spd triples after the position");
  std::vector<sim::WindSample> samples;
  for (size_t k = 0; k < data.size(); k += 3)
    samples.push_back({wind_alt(*data[k]), data[k + 1]->num, units::kt_to_ms(data[k + 2]->num)});
  SQUAWK_RETURN_IF_ERROR(s.add_wind_profile(p.lat, p.lon, samples));
  return std::string();
}

// GETWIND lat,lon,[alt]
Result<std::string> getwind(Call& c) {
  const GeoPoint p = c[0].pos;
  const sim::WindNE w = c.stack.sim().wind().at(p.lat, p.lon, c.has(1) ? c[1].num : 0.0);
  double dir = std::atan2(w.east, w.north) / units::kDeg + 180.0;
  dir = std::fmod(dir, 360.0);
  const double spd = std::hypot(w.north, w.east);
  return "WIND AT " + text::fmt_double(p.lat, 5) + ", " + text::fmt_double(p.lon, 5) + ": " +
         std::to_string(static_cast<int>(std::lround(dir)) % 360) + "/" +
         std::to_string(std::lround(units::ms_to_kt(spd)));
}

}  // namespace

void add_perf_commands(std::vector<CommandDecl>& out) {
  out.push_back({"PERF", {}, "[txt],[string]", "PERF [OPENAP [dir]/CLASS]",
                 "Selects the performance model for every aircraft: OpenAP per type from an OpenAP data folder "
                 "(dir, or the one SQUAWK_OPENAP / --openap names), or squawk's four type classes (CLASS, also "
                 "LEGACY). Without arguments shows the model in use.",
                 {"PERF OPENAP", "PERF OPENAP /usr/lib/python3/dist-packages/openap/data", "PERF CLASS"}, perf,
                 {}});
  out.push_back({"WIND",
                 {},
                 "latlon,[float/alt/txt],...",
                 "WIND lat,lon,[alt],dir,spd,[alt,dir,spd,...]",
                 "Adds a wind definition at a position: a direction (where it blows from, deg) "
                 "and speed (kt) for all altitudes, or altitude/direction/speed triples for a "
                 "profile, altitudes in feet (an FL value is read as BlueSky reads it, its metres "
                 "taken as feet: FL300 is 2787 m). Several positions are blended by inverse "
                 "squared distance. WIND lat,lon,DEL clears the wind.",
                 {"WIND 52 4 270 40", "WIND 52 4 10000 250 20 30000 270 60"},
                 wind,
                 {}});
  out.push_back({"GETWIND", {}, "latlon,[alt]", "GETWIND lat,lon,[alt]",
                 "Shows the wind at a position (and altitude) as direction/speed in kt.", {"GETWIND 52 4 FL200"},
                 getwind, {}});
}

}  // namespace squawk::command
