#include "command/args.h"

#include "command/line.h"
#include "core/geo.h"
#include "core/text.h"

namespace squawk::command {

namespace {

struct TypeName {
  const char* name;
  ArgType type;
  const char* noun;
};

constexpr TypeName kTypes[] = {
    {"acid", ArgType::kAcid, "aircraft id"},      {"txt", ArgType::kTxt, "word"},
    {"word", ArgType::kWord, "word"},             {"string", ArgType::kString, "text"},
    {"float", ArgType::kFloat, "number"},         {"int", ArgType::kInt, "integer"},
    {"onoff", ArgType::kOnOff, "on/off switch"},  {"alt", ArgType::kAlt, "altitude"},
    {"spd", ArgType::kSpd, "speed"},              {"vspd", ArgType::kVspd, "vertical speed"},
    {"hdg", ArgType::kHdg, "heading"},            {"time", ArgType::kTime, "time"},
    {"latlon", ArgType::kLatLon, "position"},     {"wpt", ArgType::kWpt, "waypoint"},
    {"wpinroute", ArgType::kWpInRoute, "route waypoint"},
};

const TypeName& info(ArgType t) {
  for (const auto& n : kTypes)
    if (n.type == t) return n;
  return kTypes[0];
}

std::string no_navdata_hint(const ParseContext& ctx) {
  return ctx.navdb ? std::string() : std::string(" (no navdata loaded: pass --navdata DIR or set SQUAWK_NAVDATA)");
}

// Parses one alternative; `reader` advances only on success (the caller
// passes a copy).
Result<ArgValue> parse_one(ArgType t, ArgReader& r, const ParseContext& ctx, GeoPoint& ref,
                           int& last_acid) {
  ArgValue v;
  v.present = true;
  v.type = t;
  if (t == ArgType::kString) {
    v.text = std::string(r.rest());
    r.clear();
    return v;
  }
  if (t == ArgType::kLatLon || t == ArgType::kWpt) {
    SQUAWK_ASSIGN_OR_RETURN(v, parse_position(r, ctx, ref));
    v.type = t;
    if (t == ArgType::kLatLon && ctx.traffic->index_of(v.text) < 0) ref = v.pos;
    return v;
  }
  const std::string token = r.next();
  v.text = t == ArgType::kWord ? token : text::upper(token);
  switch (t) {
    case ArgType::kAcid: {
      if (v.text == "*") {
        if (ctx.traffic->n() == 0) return Status::not_found("'*' (every aircraft) matched no aircraft");
        for (int i = 0; i < ctx.traffic->n(); ++i) v.acids.push_back(i);
        return v;
      }
      const int i = ctx.traffic->index_of(v.text);
      if (i < 0) return Status::not_found("no aircraft " + text::quoted(v.text));
      v.acids.push_back(i);
      last_acid = i;
      ref = {ctx.traffic->lat[i], ctx.traffic->lon[i]};
      return v;
    }
    case ArgType::kTxt:
    case ArgType::kWord:
      return v;
    case ArgType::kFloat: {
      SQUAWK_ASSIGN_OR_RETURN(v.num, parse_float(token));
      return v;
    }
    case ArgType::kInt: {
      SQUAWK_ASSIGN_OR_RETURN(long long n, parse_int(token));
      v.num = static_cast<double>(n);
      return v;
    }
    case ArgType::kOnOff: {
      SQUAWK_ASSIGN_OR_RETURN(v.on, parse_onoff(token));
      return v;
    }
    case ArgType::kAlt: {
      SQUAWK_ASSIGN_OR_RETURN(v.num, parse_alt(token));
      return v;
    }
    case ArgType::kSpd: {
      SQUAWK_ASSIGN_OR_RETURN(v.spd, parse_spd(token));
      return v;
    }
    case ArgType::kVspd: {
      SQUAWK_ASSIGN_OR_RETURN(v.num, parse_vspd(token));
      return v;
    }
    case ArgType::kTime: {
      SQUAWK_ASSIGN_OR_RETURN(v.num, parse_time(token));
      return v;
    }
    case ArgType::kHdg: {
      if (is_hdg_number(token)) {
        SQUAWK_ASSIGN_OR_RETURN(v.num, parse_hdg(token));
        return v;
      }
      ArgReader one(token);
      auto p = parse_position(one, ctx, ref);
      if (!p || !one.at_end())
        return Status::invalid("heading " + text::quoted(token) +
                               " is not degrees (090, 236.9T) or the name of an airport, waypoint or aircraft" +
                               no_navdata_hint(ctx));
      v.num = geo::kwikqdrdist(ref.lat, ref.lon, p->pos.lat, p->pos.lon).qdr_deg;
      return v;
    }
    case ArgType::kWpInRoute: {
      if (v.text == "*") return v;
      if (last_acid < 0)
        return Status::invalid("route waypoint " + text::quoted(v.text) + " needs an aircraft before it");
      if (ctx.traffic->route[last_acid].find(v.text) < 0)
        return Status::not_found(text::quoted(v.text) + " is not in the route of " + ctx.traffic->id[last_acid]);
      return v;
    }
    default:
      return Status::internal("unhandled argument type");
  }
}

}  // namespace

const char* arg_type_name(ArgType t) { return info(t).name; }
const char* arg_type_noun(ArgType t) { return info(t).noun; }

Result<Signature> parse_signature(std::string_view types) {
  Signature sig;
  bool optional = false;
  for (const auto& raw : text::split(types, ',')) {
    std::string_view field = text::trim(raw);
    if (field.empty()) {
      if (types.empty()) break;
      return Status::invalid("type list " + text::quoted(types) + " has an empty field");
    }
    if (field == "...") {
      if (sig.params.empty()) return Status::invalid("type list " + text::quoted(types) + " starts with '...'");
      sig.repeat_last = true;
      continue;
    }
    if (sig.repeat_last) return Status::invalid("type list " + text::quoted(types) + ": '...' must come last");
    if (field.front() == '[') {
      optional = true;
      field.remove_prefix(1);
    }
    if (!field.empty() && field.back() == ']') field.remove_suffix(1);
    if (field.size() >= 3 && field.substr(field.size() - 3) == "...") {
      field.remove_suffix(3);
      sig.repeat_last = true;
    }
    ParamSpec p;
    p.optional = optional;
    for (const auto& alt : text::split(field, '/')) {
      bool found = false;
      for (const auto& n : kTypes)
        if (alt == n.name) {
          p.alternatives.push_back(n.type);
          found = true;
        }
      if (!found) return Status::invalid("type list " + text::quoted(types) + ": unknown type " + text::quoted(alt));
    }
    sig.params.push_back(std::move(p));
  }
  return sig;
}

Result<ArgValue> parse_position(ArgReader& r, const ParseContext& ctx, GeoPoint ref) {
  const std::string token = text::upper(r.next());
  ArgValue v;
  v.present = true;
  v.type = ArgType::kLatLon;
  if (token.empty()) return Status::invalid("missing position");
  if (const int i = ctx.traffic->index_of(token); i >= 0) {
    v.pos = {ctx.traffic->lat[i], ctx.traffic->lon[i]};
    v.text = token;
    return v;
  }
  if (is_lat(token)) {
    if (r.next_omitted())
      return Status::invalid("position " + text::quoted(token) + " needs a longitude after the latitude");
    const std::string lon_tok = r.next();
    SQUAWK_ASSIGN_OR_RETURN(v.pos.lat, parse_lat(token));
    SQUAWK_ASSIGN_OR_RETURN(v.pos.lon, parse_lon(lon_tok));
    return v;  // text stays empty: an unnamed point
  }
  // A runway: "EHAM/RW18L", "EHGG/RWY27", or the airport and "RW.." as two tokens.
  std::string name = token, rwy;
  if (const auto slash = token.find("/RW"); slash != std::string::npos) {
    name = token.substr(0, slash);
    rwy = token.substr(slash + 3);
  }
  if (ctx.navdb) {
    if (const NavPoint* apt = ctx.navdb->airport(name)) {
      if (rwy.empty() && text::starts_with_ci(r.rest(), "RW")) {
        ArgReader trial = r;
        const std::string second = text::upper(trial.next());
        rwy = second.substr(2);
        r = trial;
      }
      if (rwy.empty() && name != token)
        return Status::invalid("runway " + text::quoted(token) + " has no runway number after RW");
      v.text = name;
      v.pos = {apt->lat, apt->lon};
      if (!rwy.empty()) {
        SQUAWK_ASSIGN_OR_RETURN(const Threshold thr, ctx.navdb->runway(name, rwy));
        v.text = name + "/RW" + rwy;
        v.pos = {thr.lat, thr.lon};
        v.ref_hdg = thr.bearing_deg;
      }
      return v;
    }
  }
  if (ctx.user_wpts) {
    if (auto it = ctx.user_wpts->find(token); it != ctx.user_wpts->end()) {
      v.pos = it->second;
      v.text = token;
      return v;
    }
  }
  if (ctx.navdb) {
    if (const NavPoint* wp = ctx.navdb->waypoint(token, ref.lat, ref.lon)) {
      v.pos = {wp->lat, wp->lon};
      v.text = token;
      return v;
    }
  }
  return Status::not_found("position " + text::quoted(token) +
                           " is not a lat/lon pair, airport, runway, waypoint, navaid or aircraft" +
                           no_navdata_hint(ctx));
}

Result<ParsedArgs> parse_args(const Signature& sig, std::string_view argtext,
                              const ParseContext& ctx) {
  std::vector<ArgValue> out;
  ArgReader r(argtext);
  GeoPoint ref = ctx.ref;
  int last_acid = -1;
  size_t k = 0;
  while (k < sig.params.size() || (!r.at_end() && sig.repeat_last && !sig.params.empty())) {
    const ParamSpec& p = sig.params[std::min(k, sig.params.size() - 1)];
    const size_t argno = k + 1;
    ++k;
    if (r.next_omitted()) {
      const bool trailing_repeat = k > sig.params.size();
      if (!p.optional && !trailing_repeat)
        return Status::invalid("missing argument " + std::to_string(argno) + " (" +
                               arg_type_noun(p.alternatives.front()) + ")");
      if (!r.at_end()) r.next();
      out.push_back(ArgValue{});
      continue;
    }
    if (p.optional && p.alternatives.front() == ArgType::kHdg) {
      ArgReader peek = r;
      if (peek.next() == "*") {  // "CRE KL1 B738 EHAM RW06 * 0 0": heading omitted
        r = peek;
        out.push_back(ArgValue{});
        continue;
      }
    }
    Status first_error;
    bool matched = false;
    for (ArgType t : p.alternatives) {
      ArgReader trial = r;
      auto v = parse_one(t, trial, ctx, ref, last_acid);
      if (v) {
        out.push_back(std::move(*v));
        r = trial;
        matched = true;
        break;
      }
      if (first_error.is_ok()) first_error = v.status();
    }
    if (!matched)
      return first_error.with_context("argument " + std::to_string(argno));
  }
  if (!r.at_end()) {
    size_t extra = 0;
    while (!r.at_end()) {
      r.next();
      ++extra;
    }
    return Status::invalid("takes " + std::to_string(sig.params.size()) + " argument" +
                           (sig.params.size() == 1 ? "" : "s") + ", but " +
                           std::to_string(sig.params.size() + extra) + " were given");
  }
  return ParsedArgs{std::move(out), ref};
}

}  // namespace squawk::command
