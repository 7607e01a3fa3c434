#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

// The robot's body must fit along its tour. A simulated robot that drives
// through a wall or between a stool's legs scans from where no robot can be,
// and what the filter makes of those scans says nothing about a real robot
// (the home tour went through walls: docs/simulator.md, "The tour must be
// drivable"). Only distances to walls, box sides and legs are checked: a
// tour wholly inside a box or outside the outer walls passes.
struct TourObstruction {
  std::size_t from_waypoint = 0;  // the leg of the tour from this waypoint to the next
  double clearance = 0.0;         // m between the robot's centre line and the obstacle's surface
  std::string obstacle;           // what it passes, with where, for the error message
};

// The first leg of the tour whose centre line passes nearer than
// `trajectory.robot_radius` to a wall, a box side or a leg; none if it fits.
std::optional<TourObstruction> firstObstruction(const Scene& scene);

}  // namespace scanfilter::sim
