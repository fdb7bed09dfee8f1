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

struct AircraftView {
  std::string id;              // callsign as created (case kept)
  std::string type;            // ICAO type designator
  double lat_deg = 0.0;        // [deg] north positive
  double lon_deg = 0.0;        // [deg] east positive
  double hdg_deg = 0.0;        // [deg] true heading
  double alt_m = 0.0;          // [m]
  double cas_ms = 0.0;         // [m/s] calibrated airspeed; 0 when the speed is a Mach number
  double mach = 0.0;           // [-] Mach number when the speed was given as Mach, else 0
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
