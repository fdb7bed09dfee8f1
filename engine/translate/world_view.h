// The translator's read-only view of the simulation.
//
// Contract: the offline grammar reads current aircraft states (for relative
// instructions such as "climb 2000 ft" and for matching a spoken callsign)
// and the names of defined waypoints through WorldView only, so the grammar
// needs no simulation. StaticWorld is an in-memory WorldView (tests, fuzzing,
// callers without a simulation); StackWorld (stack_world.h) views a live one.
#pragma once

#include <string>
#include <vector>

namespace squawk::translate {

// What the C++ extractors read of an aircraft: callsign matching and the
// route's waypoint names. The grammar (Lua) reads the rest of the traffic
// from the same tables, named and in units as sim/fields.h's kAircraft.
struct AircraftView {
  std::string id;                  // callsign as created (case kept)
  std::vector<std::string> route;  // waypoint names in route order
};

class WorldView {
 public:
  virtual ~WorldView() = default;
  virtual std::vector<AircraftView> aircraft() const = 0;
  virtual std::vector<std::string> waypoints() const = 0;  // defined waypoint names
};

class StaticWorld : public WorldView {
 public:
  std::vector<AircraftView> aircraft() const override { return aircraft_; }
  std::vector<std::string> waypoints() const override { return waypoints_; }
  void add_aircraft(AircraftView a) { aircraft_.push_back(std::move(a)); }
  void add_waypoint(std::string name) { waypoints_.push_back(std::move(name)); }

 private:
  std::vector<AircraftView> aircraft_;
  std::vector<std::string> waypoints_;
};

}  // namespace squawk::translate
