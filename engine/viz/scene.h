// Episode scenes: a recorded episode and its top-down SVG picture (the
// paper's Fig. 2: ownship, intruders with separation circles, waypoint,
// tracks, north up, scale bar), also used for a BlueSky scenario's traffic
// (viz/traffic_scene.h).
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
  std::string info;    // second label line (e.g. "FL300 280 kt"); may be empty
  bool alert = false;  // drawn red (in conflict)
};

struct Frame {
  double t = 0;  // [s] sim time
  std::vector<Pose> aircraft;  // episodes: [0] = ownship
  std::string note;
};

struct Scene {
  std::string title;     // first line of the caption
  std::string subtitle;  // added to the second line (after time and circles)
  bool ownship = true;   // episodes: frames' aircraft[0] is the ownship, the
                         // rest intruders with separation circles; false:
                         // traffic, circles only around alert aircraft
  bool waypoint = true;  // draw the waypoint
  double wpt_lat = 0, wpt_lon = 0;  // [deg]
  double rpz_nm = 5.0;              // [NM] separation radius drawn around intruders
  double wpt_radius_km = 5.0;       // [km] waypoint capture radius
  std::vector<Frame> frames;
};

// Reads episode `episode` (-1: the first one in the file) of a recording.
// Errors name the line and what was expected, or the episode that is absent.
Result<Scene> parse_episode_jsonl(const std::string& text, long long episode = -1);

struct RenderOptions {
  double size_px = 720;  // square picture side, >= 100
  int frame = -1;        // frame whose positions are drawn; -1 = last
};

// Checks `frame` against the scene: -1 or 0 .. frames - 1; the error names
// the range.
Status check_frame(const Scene& scene, long long frame);

// The picture, north up: a caption band on top (title; time, circle radius,
// frame; north arrow), the map (tracks up to the frame, aircraft symbols
// with labels placed clear of each other and of the waypoint and start
// marks, separation circles, the ownship's closest approach to any intruder
// up to the frame), and a band below (scale bar, the frame's note). Texts
// shrink, then are cut with "...", to fit the width. Precondition: the
// scene has a frame and check_frame(scene, opt.frame) is ok.
std::string render_scene(const Scene& scene, const RenderOptions& opt = {});

}  // namespace squawk::viz
