#include "env/horizontal_cr.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/geo.h"
#include "core/units.h"

namespace squawk::env {

using units::kDeg;
using units::kREarth;

namespace {

// Position of b relative to a [m] (east, north) by BlueSky's kwikqdrdist
// (equirectangular, mean-latitude cosine), from carried cos/sin of latitude:
// cos((a + b) / 2) = sqrt((1 + cos(a + b)) / 2) for |a + b| < 180 deg.
Vec2 kwik_relative(double lat_a, double lon_a, double ca, double sa, double lat_b, double lon_b,
                   double cb, double sb) {
  double dlon = lon_b - lon_a;
  if (dlon >= 180.0) dlon -= 360.0;
  if (dlon < -180.0) dlon += 360.0;
  const double cavelat = std::sqrt(0.5 * (1.0 + ca * cb - sa * sb));
  return {kREarth * dlon * kDeg * cavelat, kREarth * (lat_b - lat_a) * kDeg};
}

Status check_range(const char* name, IntRange r, int lo, int hi) {
  if (r.lo > r.hi || r.lo < lo || r.hi > hi)
    return Status::invalid(std::string("env field '") + name + "' is {" + std::to_string(r.lo) +
                           ", " + std::to_string(r.hi) + "}: expected lo <= hi within [" +
                           std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return Status::ok();
}

Status check_positive(const char* name, double v) {
  if (!(v > 0.0) || !std::isfinite(v))
    return Status::invalid(std::string("env field '") + name + "' is " + std::to_string(v) +
                           ": expected a positive finite number");
  return Status::ok();
}

}  // namespace

Status HorizontalCrConfig::validate() const {
  if (num_intruders < 1 || num_intruders > 64)
    return Status::invalid("env field 'intruders' is " + std::to_string(num_intruders) +
                           ": expected 1..64");
  if (substeps < 1) return Status::invalid("env field 'substeps' must be at least 1");
  if (max_steps < 1) return Status::invalid("env field 'max_steps' must be at least 1");
  if (limits.speed_cap < 0.0) return Status::invalid("env field 'speed_cap' must be >= 0 (0 = none)");
  if (std::fabs(start_lat) > 80.0) return Status::invalid("env field 'start_lat' must lie in [-80, 80] deg");
  for (auto [name, v] : {std::pair{"own_speed", own_speed}, {"dt", dt}, {"accel", limits.accel},
                         {"bank", limits.bank}, {"zone_radius", zone_radius},
                         {"reach_radius", reach_radius}, {"heading_per_action", heading_per_action},
                         {"lookahead", lookahead}, {"dist_scale", dist_scale},
                         {"speed_scale", speed_scale}, {"mvp_margin", mvp_margin}})
    SQUAWK_RETURN_IF_ERROR(check_positive(name, v));
  SQUAWK_RETURN_IF_ERROR(check_range("dpsi", dpsi, -360, 360));
  SQUAWK_RETURN_IF_ERROR(check_range("cpa", cpa, 0, 1000));
  SQUAWK_RETURN_IF_ERROR(check_range("tlos", tlos, 0, 100000));
  SQUAWK_RETURN_IF_ERROR(check_range("waypoint_distance", waypoint_distance, 1, 5000));
  return Status::ok();
}

Result<HorizontalCrEnv> HorizontalCrEnv::make(HorizontalCrConfig config) {
  SQUAWK_RETURN_IF_ERROR(config.validate());
  return HorizontalCrEnv(std::move(config));
}

HorizontalCrEnv::HorizontalCrEnv(HorizontalCrConfig config) : config_(std::move(config)) {
  const auto n = static_cast<size_t>(config_.num_intruders);
  for (auto* v : {&obs_.intruder_distance, &obs_.cos_difference_pos, &obs_.sin_difference_pos,
                  &obs_.x_difference_speed, &obs_.y_difference_speed})
    v->assign(n, 0.0);
  rel_.assign(n, {});
  dist_.assign(n, 0.0);
}

Result<ObservationMirror> observation_mirror(const HorizontalCrConfig& c) {
  const double cap = c.limits.speed_cap;
  if (cap > 0.0 && cap < c.own_speed)
    return Status::invalid("mirror symmetry needs a constant ownship speed, but speed_cap " +
                           std::to_string(cap) + " m/s slows own_speed " + std::to_string(c.own_speed) +
                           " m/s (use speed_cap = 0 or >= own_speed)");
  return env::observation_mirror(c.num_intruders, c.own_speed / c.speed_scale);
}

EpisodeSetup::Intruder creconfs(const HorizontalCrConfig& c, double dpsi, double cpa_nm,
                                double tlos) {
  const double gs = c.own_speed, trk_o = 0.0;
  const double pzr = c.zone_radius, cpa = cpa_nm * units::kNm;
  const double trk = trk_o + dpsi * kDeg;
  const double gsn = gs * std::cos(trk), gse = gs * std::sin(trk);
  const double vreln = gs * std::cos(trk_o) - gsn, vrele = gs * std::sin(trk_o) - gse;
  const double vrel = std::sqrt(vreln * vreln + vrele * vrele);
  const double drelcpa = tlos * vrel + (cpa > pzr ? 0.0 : std::sqrt(pzr * pzr - cpa * cpa));
  const double dist = std::sqrt(drelcpa * drelcpa + cpa * cpa);
  const double rd = drelcpa / dist, rx = cpa / dist;
  const double brn = std::atan2(-rx * vreln + rd * vrele, rd * vreln + rx * vrele) / kDeg;
  const geo::LatLon pos = geo::kwikpos(c.start_lat, c.start_lon, brn, dist / units::kNm);
  return {pos.lat_deg, pos.lon_deg, std::atan2(gse, gsn) / kDeg, std::sqrt(gsn * gsn + gse * gse)};
}

EpisodeSetup HorizontalCrEnv::draw_setup(Rng& rng) const {
  const HorizontalCrConfig& c = config_;
  EpisodeSetup s;
  for (int i = 0; i < c.num_intruders; ++i) {
    const auto dpsi = static_cast<double>(rng.uniform_int(c.dpsi.lo, c.dpsi.hi));
    const auto cpa = static_cast<double>(rng.uniform_int(c.cpa.lo, c.cpa.hi));
    const auto tlos = static_cast<double>(rng.uniform_int(c.tlos.lo, c.tlos.hi));
    s.intruders.push_back(creconfs(c, dpsi, cpa, tlos));
  }
  const auto wpt_km = static_cast<double>(rng.uniform_int(c.waypoint_distance.lo, c.waypoint_distance.hi));
  const geo::LatLon w = geo::gc_destination(c.start_lat, c.start_lon, 0.0, wpt_km * 1000.0);
  s.waypoint_lat = w.lat_deg;
  s.waypoint_lon = w.lon_deg;
  return s;
}

bool HorizontalCrEnv::reset(Rng& rng, uint64_t episode_index) {
  return start(draw_setup(rng), episode_index);
}

Result<bool> HorizontalCrEnv::reset_to(const EpisodeSetup& setup, uint64_t episode_index) {
  if (setup.intruders.size() != static_cast<size_t>(config_.num_intruders))
    return Status::invalid("episode setup has " + std::to_string(setup.intruders.size()) +
                           " intruders, expected " + std::to_string(config_.num_intruders));
  return start(setup, episode_index);
}

bool HorizontalCrEnv::start(const EpisodeSetup& setup, uint64_t episode_index) {
  fleet_.clear();
  fleet_.add(config_.start_lat, config_.start_lon, 0.0, config_.own_speed);
  for (const auto& in : setup.intruders) fleet_.add(in.lat, in.lon, in.hdg, in.tas);
  wpt_lat_ = setup.waypoint_lat;
  wpt_lon_ = setup.waypoint_lon;
  wpt_cos_lat_ = std::cos(wpt_lat_ * kDeg);
  wpt_sin_lat_ = std::sin(wpt_lat_ * kDeg);
  sim_time_ = 0.0;
  done_ = false;
  stats_ = EpisodeStats{};
  stats_.index = episode_index;
  compute_observation();
  stats_.min_separation = dist_.empty() ? 0.0 : *std::min_element(dist_.begin(), dist_.end());
  if (observer_) observer_->on_reset(*this);
  if (config_.rules == Rules::kGym) return true;
  run_automatic();
  return !done_;
}

void HorizontalCrEnv::compute_observation() {
  const Fleet& f = fleet_;
  const double lat0 = f.lat(0), lon0 = f.lon(0), c0 = f.cos_lat(0), s0 = f.sin_lat(0);
  const double ch = f.cos_hdg(0), sh = f.sin_hdg(0), gs0 = f.tas(0);
  const double inv_d = 1.0 / config_.dist_scale, inv_v = 1.0 / config_.speed_scale;
  for (int i = 0; i < config_.num_intruders; ++i) {
    const int j = i + 1;
    const auto k = static_cast<size_t>(i);
    const Vec2 p = kwik_relative(lat0, lon0, c0, s0, f.lat(j), f.lon(j), f.cos_lat(j), f.sin_lat(j));
    const double d = std::sqrt(p.x * p.x + p.y * p.y);
    rel_[k] = p;
    dist_[k] = d;
    // qdr = atan2(p.x, p.y): cos qdr = p.y / d, sin qdr = p.x / d (qdr = 0 when d = 0).
    const double cq = d > 0.0 ? p.y / d : 1.0, sq = d > 0.0 ? p.x / d : 0.0;
    obs_.intruder_distance[k] = d * inv_d;
    obs_.cos_difference_pos[k] = ch * cq + sh * sq;
    obs_.sin_difference_pos[k] = sh * cq - ch * sq;
    const double chi = f.cos_hdg(j), shi = f.sin_hdg(j), gsi = f.tas(j);
    obs_.x_difference_speed[k] = -(ch * chi + sh * shi) * gsi * inv_v;
    obs_.y_difference_speed[k] = (gs0 - (sh * chi - ch * shi) * gsi) * inv_v;
  }
  const Vec2 w = kwik_relative(lat0, lon0, c0, s0, wpt_lat_, wpt_lon_, wpt_cos_lat_, wpt_sin_lat_);
  wpt_dist_ = std::sqrt(w.x * w.x + w.y * w.y);
  wpt_qdr_ = geo::wrap360(std::atan2(w.x, w.y) / kDeg);
  const double cw = wpt_dist_ > 0.0 ? w.y / wpt_dist_ : 1.0, sw = wpt_dist_ > 0.0 ? w.x / wpt_dist_ : 0.0;
  obs_.waypoint_distance = wpt_dist_ * inv_d;
  obs_.cos_drift = ch * cw + sh * sw;
  obs_.sin_drift = sh * cw - ch * sw;
}

int HorizontalCrEnv::intruders_in_zone() const {
  int n = 0;
  for (double d : dist_) n += d < config_.zone_radius;
  return n;
}

StepFacts HorizontalCrEnv::step_facts(double hdg_before) const {
  StepFacts f;
  f.step = stats_.steps;
  f.intrusions = intruders_in_zone();
  f.substep_intrusions = substep_intrusions_;
  if (f.intrusions > 0 || f.substep_intrusions > 0) {
    double best = config_.zone_radius;
    const Vec2 vo{fleet_.gs_east(0), fleet_.gs_north(0)};
    for (int i = 0; i < config_.num_intruders; ++i) {
      const auto k = static_cast<size_t>(i);
      if (f.intrusions > 0 && dist_[k] >= config_.zone_radius) continue;
      const Vec2 w{fleet_.gs_east(i + 1) - vo.x, fleet_.gs_north(i + 1) - vo.y};
      best = std::min(best, closest_approach(rel_[k], w, config_.zone_radius).dcpa);
    }
    f.cpa_ratio = best / config_.zone_radius;
  }
  f.drift = geo::gym_wrap180(fleet_.hdg(0) - wpt_qdr_);
  f.heading_change = geo::wrap180(fleet_.hdg(0) - hdg_before);
  f.waypoint_distance = wpt_dist_;
  f.reached = wpt_dist_ < config_.reach_radius;
  return f;
}

void HorizontalCrEnv::advance(double hdg_cmd) {
  fleet_.set_heading(0, hdg_cmd);
  const bool each_substep = config_.rules == Rules::kPaper && config_.substep_intrusions;
  const double r2 = config_.zone_radius * config_.zone_radius;
  const double dlat_zone = config_.zone_radius / (kREarth * kDeg);  // [deg]
  const Fleet& f = fleet_;
  substep_intrusions_ = 0;
  for (int s = 0; s < config_.substeps; ++s) {
    fleet_.step(config_.dt, config_.limits);
    sim_time_ += config_.dt;
    if (!each_substep) continue;
    const double lat0 = f.lat(0), lon0 = f.lon(0), c0 = f.cos_lat(0), s0 = f.sin_lat(0);
    for (int j = 1; j <= config_.num_intruders; ++j) {
      if (std::fabs(f.lat(j) - lat0) > dlat_zone) continue;  // north-south gap alone exceeds the zone
      const Vec2 p = kwik_relative(lat0, lon0, c0, s0, f.lat(j), f.lon(j), f.cos_lat(j), f.sin_lat(j));
      if (p.x * p.x + p.y * p.y < r2) {
        ++stats_.intrusions;
        ++substep_intrusions_;
        break;
      }
    }
  }
  ++stats_.steps;
  stats_.sim_time = sim_time_;
  compute_observation();
  for (double d : dist_) stats_.min_separation = std::min(stats_.min_separation, d);
  if (config_.rules == Rules::kPaper && !config_.substep_intrusions && intruders_in_zone() > 0)
    ++stats_.intrusions;
}

bool HorizontalCrEnv::conflict_ahead() const {
  const double tas = fleet_.tas(0);
  const Vec2 vo{tas * std::sin(wpt_qdr_ * kDeg), tas * std::cos(wpt_qdr_ * kDeg)};
  for (int i = 0; i < config_.num_intruders; ++i) {
    const Vec2 w{fleet_.gs_east(i + 1) - vo.x, fleet_.gs_north(i + 1) - vo.y};
    if (closest_approach(rel_[static_cast<size_t>(i)], w, config_.zone_radius).conflict(config_.lookahead))
      return true;
  }
  return false;
}

double HorizontalCrEnv::mvp_action() const {
  const Vec2 vo{fleet_.gs_east(0), fleet_.gs_north(0)};
  Vec2 dv;
  bool any = false;
  for (int i = 0; i < config_.num_intruders; ++i) {
    const auto k = static_cast<size_t>(i);
    const Vec2 w{fleet_.gs_east(i + 1) - vo.x, fleet_.gs_north(i + 1) - vo.y};
    const Cpa c = closest_approach(rel_[k], w, config_.zone_radius);
    if (!c.conflict(config_.lookahead)) continue;
    const Vec2 d = mvp_velocity_change(rel_[k], w, c.tcpa, config_.zone_radius * config_.mvp_margin);
    dv.x += d.x;
    dv.y += d.y;
    any = true;
  }
  // No conflict on the current track: hold it while the direct route is in
  // conflict, else turn toward the waypoint (BlueSky's resume-navigation idea).
  double target = fleet_.hdg(0);
  if (any) {
    target = std::atan2(vo.x + dv.x, vo.y + dv.y) / kDeg;
  } else if (!conflict_ahead()) {
    target = wpt_qdr_;
  }
  return std::clamp(geo::wrap180(target - fleet_.hdg(0)) / config_.heading_per_action, -1.0, 1.0);
}

void HorizontalCrEnv::finish(bool truncated) {
  done_ = true;
  stats_.truncated = truncated;
  stats_.sim_time = sim_time_;
  stats_.success = config_.rules == Rules::kGym
                       ? stats_.intrusions == 0
                       : stats_.reached && !truncated && stats_.intrusions == 0;
  if (observer_) observer_->on_end(*this, stats_);
}

double HorizontalCrEnv::reward_of(const StepFacts& f) const {
  if (config_.reward_fn) return config_.reward_fn(f);
  return config_.rules == Rules::kGym ? gym_reward(config_.weights, f) : paper_reward(config_.weights, f);
}

double HorizontalCrEnv::step(double action) {
  if (done_) return 0.0;
  const double a = std::clamp(std::isfinite(action) ? action : 0.0, -1.0, 1.0);
  const double hdg_before = fleet_.hdg(0);
  StepInfo info;
  info.agent = true;
  info.action = a;
  info.hdg_cmd = hdg_before + a * config_.heading_per_action;
  advance(info.hdg_cmd);
  info.facts = step_facts(hdg_before);
  const StepFacts& f = info.facts;
  info.reward = reward_of(f);
  stats_.total_reward += info.reward;
  ++stats_.decisions;
  if (config_.rules == Rules::kGym) stats_.intrusions += f.intrusions;
  if (observer_) observer_->on_step(*this, info);
  double reward = info.reward;
  if (f.reached) {
    stats_.reached = true;
    finish(false);
  } else if (stats_.steps >= config_.max_steps) {
    finish(true);
  } else if (config_.rules == Rules::kPaper) {
    reward += run_automatic();
  }
  return reward;
}

double HorizontalCrEnv::run_automatic() {
  double reward = 0.0;
  while (!done_) {
    if (conflict_ahead()) return reward;
    const double hdg_before = fleet_.hdg(0);
    StepInfo info;
    info.hdg_cmd = wpt_qdr_;
    advance(info.hdg_cmd);
    info.facts = step_facts(hdg_before);
    info.reward = reward_of(info.facts);
    reward += info.reward;
    stats_.total_reward += info.reward;
    if (observer_) observer_->on_step(*this, info);
    if (info.facts.reached) {
      stats_.reached = true;
      finish(false);
    } else if (stats_.steps >= config_.max_steps) {
      finish(true);
    }
  }
  return reward;
}

}  // namespace squawk::env
