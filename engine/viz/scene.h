// Episode scenes: the recorded-episode format and its top-down SVG picture
// (the paper's Fig. 2: ownship, intruders with protected-zone circles,
// waypoint, tracks, north up, scale bar).
//
// Recording format (JSON lines, written by the demo and `squawk eval --record`):
//   line 1: {"episode": {"title": str, "waypoint": {"lat": deg, "lon": deg},
//            "rpz_nm": NM, "wpt_radius_km": km}}
//   then one line per recorded state:
//           {"t": s, "aircraft": [{"id": str, "lat": deg, "lon": deg, "hdg": deg}, ...],
//            "action": number (optional), "note": str (optional)}
//   aircraft[0] is the ownship. Unknown keys are ignored.
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

// Errors name the line and what was expected.
Result<Scene> parse_episode_jsonl(const std::string& text);
std::string to_jsonl_header(const Scene& scene);
std::string to_jsonl_frame(const Frame& frame, double action, bool has_action);

struct RenderOptions {
  double size_px = 720;  // square picture side
  int frame = -1;        // frame whose positions are drawn; -1 = last
};
std::string render_scene(const Scene& scene, const RenderOptions& opt = {});

}  // namespace squawk::viz
