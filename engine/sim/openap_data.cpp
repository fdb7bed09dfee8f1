#include "sim/openap_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "core/files.h"
#include "core/text.h"
#include "core/units.h"

namespace squawk::sim {

namespace {

using Dict = std::map<std::string, std::string>;  // "section.key" -> value text

// The block-mapping subset of YAML the OpenAP files use: "key: value" lines,
// nesting by indentation, '#' comments; list items are skipped.
Dict read_yaml(const std::string& text) {
  Dict d;
  std::vector<std::pair<size_t, std::string>> stack;  // (indent, key)
  for (const std::string& raw : text::split(text, '\n')) {
    std::string line = raw;
    if (const size_t h = line.find('#'); h != std::string::npos) line.erase(h);
    const size_t indent = line.find_first_not_of(" \t");
    if (indent == std::string::npos) continue;
    const std::string_view body = text::trim(line);
    if (body.empty() || body[0] == '-') continue;
    const size_t colon = body.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string key(text::trim(body.substr(0, colon)));
    const std::string value(text::trim(body.substr(colon + 1)));
    while (!stack.empty() && stack.back().first >= indent) stack.pop_back();
    std::string full;
    for (const auto& [ind, k] : stack) full.append(k).append(".");
    full.append(key);
    if (value.empty()) stack.emplace_back(indent, key);
    else d[full] = value;
  }
  return d;
}

// orig -> new from a _synonym.csv (lower-case names).
std::map<std::string, std::string> read_synonyms(const std::string& path) {
  std::map<std::string, std::string> m;
  auto text = files::read(path);
  if (!text.is_ok()) return m;
  for (const std::string& line : text::split(text.value(), '\n')) {
    const auto f = text::split(line, ',');
    if (f.size() < 2) continue;
    const std::string a = text::lower(text::trim(f[0])), b = text::lower(text::trim(f[1]));
    if (a == "orig" || a.empty() || b.empty()) continue;
    m.emplace(a, b);
  }
  return m;
}

struct WrapVar {
  double opt, min, max;
};
using Wrap = std::map<std::string, WrapVar>;

// WRAP table: variable, phase, name (several words), opt, min, max, model, params.
Wrap read_wrap(const std::string& text) {
  Wrap w;
  for (const std::string& line : text::split(text, '\n')) {
    const auto t = text::split_ws(line);
    if (t.size() < 8 || t[0] == "variable") continue;
    const size_t n = t.size();
    const auto o = text::to_double(t[n - 5]), lo = text::to_double(t[n - 4]), hi = text::to_double(t[n - 3]);
    if (o && lo && hi) w[t[0]] = {*o, *lo, *hi};
  }
  return w;
}

struct Engine {
  double max_thrust, bpr;
};

class Loader {
 public:
  explicit Loader(std::string dir) : dir_(std::move(dir)) {}

  Status prepare() {
    ac_syn_ = read_synonyms(dir_ + "/aircraft/_synonym.csv");
    wrap_syn_ = read_synonyms(dir_ + "/wrap/_synonym.csv");
    drag_syn_ = read_synonyms(dir_ + "/dragpolar/_synonym.csv");
    auto eng = files::read(dir_ + "/engine/engines.csv");
    if (!eng.is_ok()) return Status::not_found(dir_ + "/engine/engines.csv: cannot read the OpenAP engine table");
    const auto lines = text::split(eng.value(), '\n');
    if (lines.empty()) return Status::invalid(dir_ + "/engine/engines.csv: empty");
    const auto head = text::split(lines[0], ',');
    int c_name = -1, c_bpr = -1, c_thr = -1;
    for (size_t c = 0; c < head.size(); ++c) {
      const std::string h(text::trim(head[c]));
      if (h == "name") c_name = static_cast<int>(c);
      if (h == "bpr") c_bpr = static_cast<int>(c);
      if (h == "max_thrust") c_thr = static_cast<int>(c);
    }
    if (c_name < 0 || c_bpr < 0 || c_thr < 0)
      return Status::invalid(dir_ + "/engine/engines.csv: expected columns name, bpr, max_thrust");
    for (size_t l = 1; l < lines.size(); ++l) {
      const auto f = text::split(lines[l], ',');
      if (static_cast<int>(f.size()) <= std::max({c_name, c_bpr, c_thr})) continue;
      const auto b = text::to_double(f[c_bpr]), m = text::to_double(f[c_thr]);
      if (b && m) engines_.emplace_back(text::upper(text::trim(f[c_name])), Engine{*m, *b});
    }
    return Status::ok();
  }

  std::vector<std::string> type_names() const {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir_ + "/aircraft", ec)) {
      const auto p = e.path();
      if (p.extension() == ".yml") names.push_back(text::lower(p.stem().string()));
    }
    for (const auto& [orig, nw] : ac_syn_) names.push_back(orig);
    return names;
  }

  // The data of type `mdl` (lower-case), or nullopt when a file is missing.
  std::optional<OpenapType> build(const std::string& mdl) const {
    std::string acname = mdl;
    if (!files::exists(dir_ + "/aircraft/" + acname + ".yml")) {
      const auto s = ac_syn_.find(mdl);
      if (s == ac_syn_.end()) return std::nullopt;
      acname = s->second;
    }
    auto ac_text = files::read(dir_ + "/aircraft/" + acname + ".yml");
    auto wrap_text = read_synonym_file("wrap", mdl, ".txt", wrap_syn_);
    auto drag_text = read_synonym_file("dragpolar", mdl, ".yml", drag_syn_);
    if (!ac_text.is_ok() || !wrap_text || !drag_text) return std::nullopt;
    const Dict ac = read_yaml(ac_text.value()), dp = read_yaml(*drag_text);
    const Wrap w = read_wrap(*wrap_text);
    auto num = [](const Dict& d, const char* k) -> std::optional<double> {
      const auto it = d.find(k);
      return it == d.end() ? std::nullopt : text::to_double(it->second);
    };
    auto var = [&](const char* k) -> const WrapVar* {
      const auto it = w.find(k);
      return it == w.end() ? nullptr : &it->second;
    };
    const char* speeds[] = {"ic_va_avg", "cl_v_cas_const", "cr_v_cas_mean", "de_v_cas_const", "fa_va_avg"};
    const char* climbs[] = {"ic_vs_avg", "cl_vs_avg_pre_cas", "cl_vs_avg_cas_const", "cl_vs_avg_mach_const"};
    for (const char* k : speeds)
      if (!var(k)) return std::nullopt;
    for (const char* k : climbs)
      if (!var(k)) return std::nullopt;
    for (const char* k : {"to_v_lof", "cr_v_mach_max", "cr_h_max", "to_acc_tof"})
      if (!var(k)) return std::nullopt;

    OpenapType t;
    t.name = text::upper(acname);
    if (acname == mdl && ac.count("aircraft")) t.title = std::string(text::trim(ac.at("aircraft")));
    t.vminto = var("to_v_lof")->min;
    t.vminic = var("ic_va_avg")->min;
    t.vmaxic = var("ic_va_avg")->max;
    t.vminer = 1e9, t.vmaxer = -1e9;
    for (const char* k : speeds) t.vminer = std::min(t.vminer, var(k)->min), t.vmaxer = std::max(t.vmaxer, var(k)->max);
    t.vminap = var("fa_va_avg")->min;
    t.vmaxap = var("fa_va_avg")->max;
    t.mmo = var("cr_v_mach_max")->opt;
    t.hmax = var("cr_h_max")->opt * 1000.0;
    t.axmax0 = var("to_acc_tof")->max;
    t.vsmax = -1e9, t.vsmin = 1e9;
    for (const char* k : climbs) t.vsmax = std::max(t.vsmax, var(k)->max), t.vsmin = std::min(t.vsmin, var(k)->min);

    const auto oew = num(ac, "oew"), mtow = num(ac, "mtow"), area = num(ac, "wing.area"), span = num(ac, "wing.span");
    const auto neng = num(ac, "engine.number");
    const auto eng_it = ac.find("engine.default");
    if (!oew || !mtow || !area || !span || !neng || eng_it == ac.end()) return std::nullopt;
    const Engine* e = engine(eng_it->second);
    if (!e) return std::nullopt;
    t.mass = 0.5 * (*oew + *mtow);
    t.sref = *area;
    t.thrust0 = *neng * e->max_thrust;
    t.bpr = e->bpr;

    const auto cd0 = num(dp, "clean.cd0"), k = num(dp, "clean.k"), gear = num(dp, "gears");
    const auto lf = num(dp, "flaps.lambda_f"), cfc = num(dp, "flaps.cf/c"), sfs = num(dp, "flaps.Sf/S");
    if (!cd0 || !k || !gear || !lf || !cfc || !sfs) return std::nullopt;
    const double flap_to = 15.0, flap_ld = 40.0;  // [deg] BlueSky's assumed flap settings
    auto dcd = [&](double flap) {
      const double s = std::sin(flap * units::kDeg);
      return *lf * std::pow(*cfc, 1.38) * *sfs * s * s;
    };
    const auto mount = ac.find("engine.mount");
    const double de_per_deg = (mount != ac.end() && mount->second == "rear") ? 0.0046 : 0.0026;
    const double ar = *span * *span / *area;
    t.cd0_clean = *cd0;
    t.k_clean = *k;
    t.cd0_to = *cd0 + dcd(flap_to);
    t.cd0_ld = *cd0 + dcd(flap_ld);
    t.k_to = 1.0 / (1.0 / *k + units::kPi * ar * de_per_deg * flap_to);
    t.k_ld = 1.0 / (1.0 / *k + units::kPi * ar * de_per_deg * flap_ld);
    t.cd_gear = *gear;
    return t;
  }

 private:
  std::optional<std::string> read_synonym_file(const char* sub, const std::string& mdl, const char* ext,
                                               const std::map<std::string, std::string>& syn) const {
    std::string name = mdl;
    const std::string base = dir_ + "/" + sub + "/";
    if (!files::exists(base + name + ext)) {
      const auto s = syn.find(mdl);
      if (s == syn.end()) return std::nullopt;
      name = s->second;
    }
    auto r = files::read(base + name + ext);
    if (!r.is_ok()) return std::nullopt;
    return std::move(r).value();
  }

  const Engine* engine(const std::string& name) const {
    const std::string want = text::upper(text::trim(name));
    for (const auto& [n, e] : engines_)
      if (n.rfind(want, 0) == 0) return &e;
    return nullptr;
  }

  std::string dir_;
  std::map<std::string, std::string> ac_syn_, wrap_syn_, drag_syn_;
  std::vector<std::pair<std::string, Engine>> engines_;
};

std::mutex g_mu;
bool g_loaded = false;
std::shared_ptr<const OpenapData> g_default;

}  // namespace

Result<std::shared_ptr<const OpenapData>> OpenapData::load(const std::string& dir) {
  if (!files::exists(dir + "/aircraft"))
    return Status::not_found(dir + ": not an OpenAP data folder (expected aircraft/, wrap/, dragpolar/, engine/)");
  Loader ld(dir);
  SQUAWK_RETURN_IF_ERROR(ld.prepare());
  auto data = std::make_shared<OpenapData>();
  data->dir_ = dir;
  for (const std::string& mdl : ld.type_names())
    if (auto t = ld.build(mdl)) data->types_[text::upper(mdl)] = std::move(*t);
  const auto b744 = data->types_.find("B744");
  if (b744 == data->types_.end())
    return Status::invalid(dir + ": OpenAP data for B744 (the fallback type) is incomplete");
  data->fallback_ = &b744->second;
  return std::shared_ptr<const OpenapData>(std::move(data));
}

const OpenapType* OpenapData::find(std::string_view actype) const {
  const auto it = types_.find(text::upper(text::trim(actype)));
  return it == types_.end() ? fallback_ : &it->second;
}

bool OpenapData::has(std::string_view actype) const {
  return types_.count(text::upper(text::trim(actype))) > 0;
}

std::shared_ptr<const OpenapData> default_openap() {
  std::lock_guard<std::mutex> lock(g_mu);
  if (!g_loaded) {
    g_loaded = true;
    if (const char* dir = std::getenv("SQUAWK_OPENAP"); dir && *dir) {
      auto r = OpenapData::load(dir);
      if (r.is_ok()) g_default = r.value();
      else std::fprintf(stderr, "SQUAWK_OPENAP: %s\n", r.status().message().c_str());
    }
  }
  return g_default;
}

Status set_default_openap(const std::string& dir) {
  SQUAWK_ASSIGN_OR_RETURN(auto data, OpenapData::load(dir));
  std::lock_guard<std::mutex> lock(g_mu);
  g_loaded = true;
  g_default = std::move(data);
  return Status::ok();
}

std::vector<std::pair<std::string, std::string>> OpenapData::titles() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [key, t] : types_) out.emplace_back(key, t.title);
  return out;
}

}  // namespace squawk::sim
