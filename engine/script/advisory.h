// AdvisoryPhraser: the Lua template (prompts/advisory.lua) that says a
// deconfliction decision in controller English, called from C++ (the demo).
//
// Contract: load() runs the file in its own sandboxed Vm; the file returns a
// table with advise(d) (fields documented in prompts/advisory.lua). phrase()
// returns the line it produced, or an error with the Lua message when the
// function fails or returns something other than a non-empty string.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/status.h"
#include "script/vm.h"

namespace squawk::script {

struct Advisory {
  std::string callsign;
  double action = 0.0;           // [-] units of 45 deg
  int heading = 360;             // [deg] heading to fly, 1..360
  double current_heading = 0.0;  // [deg]
  std::string turn;              // "left", "right" or "none"
  struct Traffic {
    std::string id;
    int clock = 12;          // [-] clock position 1..12 relative to the nose
    double distance_nm = 0;  // [NM]
  };
  std::optional<Traffic> traffic;
};

class AdvisoryPhraser {
 public:
  static Result<AdvisoryPhraser> load(const std::string& path, const VmOptions& options);
  Result<std::string> phrase(const Advisory& a);

 private:
  std::shared_ptr<Vm> vm_;
};

}  // namespace squawk::script
