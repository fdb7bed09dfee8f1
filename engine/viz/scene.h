// Episode scenes: a recorded episode and its top-down SVG picture (the
// paper's Fig. 2: ownship, intruders with separation circles, waypoint,
// tracks, north up, scale bar).
//
// Recorded episodes are the JSON lines of env::JsonlRecorder (env/recorder.h;
// written by `squawk eval --record` and `squawk demo --record`): a "reset"
// event, "step" events and an "end" event per episode, possibly interleaved
// with other episodes' lines. Ownship and intruder states are
// [lat, lon, hdg, tas]; the ownship is named KL001 and intruder i is named
// "i", as in BlueSky-Gym. A step may carry a "note" (the demo's advisory).
#pragma once

#include <string>
#include <vector>

#include "core/status.h"

namespace squawk::viz {

struct Pose {
  std::string id;
  double lat = 0;  // [deg]
  double lon = 0;  // [deg]
  double hdg = 0;  // [deg] true
};

struct Frame {
  double t = 0;  // [s] sim time
  std::vector<Pose> aircraft;  // [0] = ownship
  std::string note;
};

struct Scene {
  std::string title;
  double wpt_lat = 0, wpt_lon = 0;  // [deg]
  double rpz_nm = 5.0;              // [NM] separation radius drawn around intruders
  double wpt_radius_km = 5.0;       // [km] waypoint capture radius
  std::vector<Frame> frames;
};

// Reads episode `episode` (-1: the first one in the file) of a recording.
// Errors name the line and what was expected, or the episode that is absent.
Result<Scene> parse_episode_jsonl(const std::string& text, long long episode = -1);

struct RenderOptions {
  double size_px = 720;  // square picture side
  int frame = -1;        // frame whose positions are drawn; -1 = last
};
std::string render_scene(const Scene& scene, const RenderOptions& opt = {});

}  // namespace squawk::viz
