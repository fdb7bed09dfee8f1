// OpenAP performance model: what BlueSky's default performance model does
// with the per-type data of openap_data.h (facts from BlueSky
// traffic/performance/openap/{perfoap,phase,thrust}.py at 22fdf9e).
//
// Contract (all SI; altitudes [m], speeds [m/s], vs [m/s]):
// - Phase from TAS, V/S, altitude, thresholds in ft and ft/min:
//   alt <= 75 GD; 75..1000 with roc >= 150 IC, roc <= -150 AP; >= 1000 with
//   roc >= 150 CL, roc <= -150 DE; >= 10000 with |roc| <= 150 CR; else NA.
// - openap_update() (BlueSky runs it every performance_dt = 1 s of sim time,
//   before the traffic step): phase, speed envelope (vmin/vmax CAS: GD 0 /
//   vmaxic, AP vminap / vmaxap, all others vminer / vmaxer) and acceleration
//   limit axmax = (max thrust - drag) / mass, 2 m/s^2 in GD, at least 0.5.
//   Drag: 0.5 rho V^2 S (cd0 + k cl^2) with the phase's configuration (GD:
//   take-off + gear, IC: take-off, AP: landing, else clean); max thrust:
//   OpenAP's take-off thrust ratio in GD, its three-segment in-flight model
//   otherwise (eq. in thrust.cpp).
// - openap_limit_tas(): the intent TAS is read as CAS at the intent altitude
//   (already capped at the ceiling), clipped to [vmin, vmax], converted back
//   and capped at MMO there: the envelope is evaluated at the selected
//   altitude.
// - openap_limit_vs(): an intent climb rate above vsmax becomes
//   (1 - ax/axmax) vsmax (ax the last step's acceleration, so accelerating
//   reduces it); in GD below the lift-off speed vminto no climb (0).
#pragma once

#include <cstdint>

#include "sim/openap_data.h"
#include "sim/performance.h"

namespace squawk::sim {

enum class FlightPhase : uint8_t { kNA = 0, kGround = 1, kInitClimb = 2, kClimb = 3, kCruise = 4, kDescent = 5, kApproach = 6 };

FlightPhase openap_phase(double alt, double vs);

// Updates phase and lim.vmin/vmax/axmax of one aircraft of type `t`.
void openap_update(const OpenapType& t, double tas, double vs, double alt, FlightPhase& phase, PerfLimits& lim);

// Maximum thrust [N] of type `t` in `phase` (OpenAP thrust model).
double openap_max_thrust(const OpenapType& t, FlightPhase phase, double tas, double alt, double vs);
// Drag [N] of type `t` in `phase` at TAS `tas` and altitude `alt`.
double openap_drag(const OpenapType& t, FlightPhase phase, double tas, double alt);

// Allowed TAS for an intent TAS at the allowed (ceiling-capped) altitude.
double openap_limit_tas(const PerfLimits& lim, double intent_tas, double allow_alt);
// Allowed |V/S| for an intent |V/S| >= 0.
double openap_limit_vs(const OpenapType& t, const PerfLimits& lim, FlightPhase phase, double intent_vs,
                       double ax, double tas);

}  // namespace squawk::sim
