// A BlueSky scenario's traffic as a Scene (viz/scene.h): the aircraft of a
// running command stack sampled from now to a given time, for
// `squawk render FILE.scn --at T`.
#pragma once

#include "command/stack.h"
#include "core/status.h"
#include "viz/scene.h"

namespace squawk::viz {

// Runs `stack` from its current time to t_end [s] (>= now), taking `frames`
// (>= 2) evenly spaced samples, the first now and the last at t_end. Each
// pose carries "FL300 280 kt" as its second label line and is an alert
// while the aircraft is in a detected conflict or loss of separation. The
// scene has no ownship and no waypoint; rpz_nm is the detector's zone.
// Error when t_end is before now or not finite, or the stack fails to run.
Result<Scene> traffic_scene(command::Stack& stack, double t_end, int frames = 40);

}  // namespace squawk::viz
