// Named shapes and the deletion area, as BlueSky declares them (basecmds.py,
// plugins/area.py): BOX, CIRCLE, POLY (POLYGON), POLYALT, LINE, POLYLINE
// (LINES), AREA. DEL of a shape is in commands_traffic.cpp.
#include "command/handler_util.h"
#include "core/text.h"

namespace squawk::command {

namespace {

// The positions from argument `from` on, as lat lon pairs.
std::vector<double> points(Call& c, size_t from) {
  std::vector<double> out;
  for (size_t k = from; k < c.args.size(); ++k)
    if (c[k].present) out.insert(out.end(), {c[k].pos.lat, c[k].pos.lon});
  return out;
}

Result<std::string> define(Call& c, sim::Shape shape) {
  SQUAWK_RETURN_IF_ERROR(c.stack.sim().define_shape(c[0].text, std::move(shape)));
  return std::string();
}

// BOX name,lat,lon,lat,lon,[top,bottom]
Result<std::string> box(Call& c) {
  return define(c, {sim::Shape::Kind::kBox, {c[1].pos.lat, c[1].pos.lon, c[2].pos.lat, c[2].pos.lon},
                    c.has(3) ? c[3].num : 1e9, c.has(4) ? c[4].num : -1e9});
}

// CIRCLE name,lat,lon,radius,[top,bottom]
Result<std::string> circle(Call& c) {
  return define(c, {sim::Shape::Kind::kCircle, {c[1].pos.lat, c[1].pos.lon, c[2].num}, c.has(3) ? c[3].num : 1e9,
                    c.has(4) ? c[4].num : -1e9});
}

// POLY name,lat,lon,lat,lon,...
Result<std::string> poly(Call& c) { return define(c, {sim::Shape::Kind::kPoly, points(c, 1)}); }

// POLYALT name,top,bottom,lat,lon,...
Result<std::string> polyalt(Call& c) {
  return define(c, {sim::Shape::Kind::kPoly, points(c, 3), c[1].num, c[2].num});
}

// LINE name,lat,lon,lat,lon / POLYLINE name,lat,lon,...
Result<std::string> line(Call& c) { return define(c, {sim::Shape::Kind::kLine, points(c, 1)}); }

// AREA shapename | AREA OFF | AREA ON | AREA lat,lon,lat,lon,[top,bottom]
Result<std::string> area(Call& c) {
  sim::Simulation& s = c.stack.sim();
  if (!c.has(0)) return s.area_active() ? "Deletion area is ON (shape " + s.area_name() + ")" : "Deletion area is OFF";
  if (c[0].type == ArgType::kTxt && !c.has(1)) {
    const std::string& name = c[0].text;
    if (s.shapes().find(name)) {
      SQUAWK_RETURN_IF_ERROR(s.set_area(name));
      return std::string();
    }
    if (name.rfind("OF", 0) == 0) {
      s.area_off();
      return std::string();
    }
    if (name.rfind("ON", 0) == 0) {
      if (s.area_name().empty()) return Status::invalid("argument 1: no deletion area defined yet");
      SQUAWK_RETURN_IF_ERROR(s.set_area(s.area_name()));
      return std::string();
    }
    return Status::not_found("argument 1: no shape " + text::quoted(name) +
                             " (define it with BOX, CIRCLE or POLY, or give a box lat,lon,lat,lon, or OFF)");
  }
  if (c[0].type == ArgType::kTxt)
    return Status::invalid("argument 1: expected a shape name, OFF, or a box lat,lon,lat,lon; got " +
                           text::quoted(c[0].text) + " with more arguments");
  for (size_t k = 1; k < 4; ++k)
    if (!c.has(k) || c[k].type == ArgType::kTxt)
      return Status::invalid("argument " + std::to_string(k + 1) + ": a box needs lat,lon,lat,lon");
  SQUAWK_RETURN_IF_ERROR(s.set_area(c[0].num, c[1].num, c[2].num, c[3].num, c.has(4) ? c[4].num : 1e9,
                                    c.has(5) ? c[5].num : -1e9));
  return std::string();
}

}  // namespace

void add_shape_commands(std::vector<CommandDecl>& out) {
  out.push_back({"BOX", {}, "txt,latlon,latlon,[alt,alt]", "BOX name,lat,lon,lat,lon,[top,bottom]",
                 "Defines (or replaces) a named box between two corners, optionally between a top and a bottom "
                 "altitude, for AREA.",
                 {"BOX TMA 51.5 3.5 53 6", "BOX HIGH 51.5 3.5 53 6 FL450 FL245"}, box, {}});
  out.push_back({"CIRCLE", {}, "txt,latlon,float,[alt,alt]", "CIRCLE name,lat,lon,radius,[top,bottom]",
                 "Defines (or replaces) a named circle: centre and radius in nautical miles (BlueSky's flat-earth "
                 "distance), optionally between a top and a bottom altitude, for AREA.",
                 {"CIRCLE CTR 52.3 4.76 20", "CIRCLE CTR 52.3 4.76 20 3000 0"}, circle, {}});
  out.push_back({"POLY", {"POLYGON"}, "txt,latlon,...", "POLY name,lat,lon,lat,lon,...",
                 "Defines (or replaces) a named polygon of three points or more, at every altitude, for AREA.",
                 {"POLY SECTOR 52 4 53 4 53 6 52 6"}, poly, {}});
  out.push_back({"POLYALT", {}, "txt,alt,alt,latlon,...", "POLYALT name,top,bottom,lat,lon,lat,lon,...",
                 "Defines (or replaces) a named polygon between a top and a bottom altitude, for AREA.",
                 {"POLYALT UPPER FL660 FL245 52 4 53 4 53 6 52 6"}, polyalt, {}});
  out.push_back({"LINE", {}, "txt,latlon,latlon", "LINE name,lat,lon,lat,lon",
                 "Defines a named line (drawn only: no aircraft is ever inside it).", {"LINE CUT 52 4 53 5"}, line,
                 {}});
  out.push_back({"POLYLINE", {"LINES", "POLYLINES"}, "txt,latlon,...", "POLYLINE name,lat,lon,lat,lon,...",
                 "Defines a named line of several segments (drawn only).", {"POLYLINE EDGE 52 4 53 5 53 6"}, line,
                 {}});
  out.push_back({"AREA", {}, "[float/txt,float,float,float,alt,alt]",
                 "AREA shapename/ON/OFF or AREA lat,lon,lat,lon,[top,bottom]",
                 "Sets the deletion area: a named shape (BOX, CIRCLE, POLY, POLYALT) or a box given here (it "
                 "becomes the shape DELAREA). Aircraft that leave it are deleted (checked every second; "
                 "aircraft that were never inside stay). AREA OFF ends it, AREA ON resumes it.",
                 {"AREA TMA", "AREA 51.5 3.5 53 6", "AREA 51.5 3.5 53 6 FL300 0", "AREA OFF"}, area, {}});
}

}  // namespace squawk::command
