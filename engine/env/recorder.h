// JsonlRecorder: an EpisodeObserver that writes one JSON object per line,
// for replay and rendering (a later `squawk render` reads these).
//
// Lines (angles [deg], positions lat/lon [deg], speeds [m/s], time [s]):
//   {"event":"reset","episode":k,"rules":"paper"|"gym","t":0,
//    "waypoint":[lat,lon],"own":[lat,lon,hdg,tas],"intruders":[[lat,lon,hdg,tas],...]}
//   {"event":"step","episode":k,"t":..,"agent":bool,"action":a,"hdg_cmd":..,
//    "reward":..,"intrusions":n,"own":[...],"intruders":[[...],...]}
//   {"event":"end","episode":k,"return":..,"success":bool,"reached":bool,
//    "truncated":bool,"steps":n,"decisions":n,"intrusions":n,"t":..}
// "action" is present only on agent steps.
#pragma once

#include <ostream>

#include "env/horizontal_cr.h"

namespace squawk::env {

class JsonlRecorder : public EpisodeObserver {
 public:
  explicit JsonlRecorder(std::ostream& out) : out_(out) {}
  void on_reset(const HorizontalCrEnv& env) override;
  void on_step(const HorizontalCrEnv& env, const StepInfo& info) override;
  void on_end(const HorizontalCrEnv& env, const EpisodeStats& stats) override;

 private:
  std::ostream& out_;
};

}  // namespace squawk::env
