// The physical facts the scripted person reacts to (design notes 2), derived
// from the simulator's plain reports, never from the controller's internals.
// Real-time safe.
#pragma once

#include <Eigen/Geometry>

#include "scenes/scenario/scenario.hpp"
#include "scenes/sim/sim_io.hpp"

namespace handover::human {

constexpr double kInReachDistance = 0.03;  ///< m, object surface to grip point
constexpr double kInReachSpeed = 0.05;     ///< m/s, object speed below which it counts as offered

struct HumanFacts {
  bool fingers_on_object = false;  ///< both robot fingers touch the object
  bool object_free = true;         ///< no robot finger touches the object
  bool object_in_reach = false;    ///< surface within 3 cm of the grip point and slower than 5 cm/s
  double object_distance = 0.0;    ///< m, grip point to the object's surface (0 inside)
  double object_speed = 0.0;       ///< m/s, linear speed of the object frame
};

/// Distance (m) from a world point to the surface of the object (0 inside).
/// The object frame sits at the shape's centre; a cylinder's axis is its z.
double distanceToObject(const scenario::ObjectSpec& object, const Eigen::Isometry3d& object_pose,
                        const Eigen::Vector3d& point_world);

/// Facts of one step from the contact report, the object's true state and
/// the hand's grip-point pose (world).
HumanFacts computeHumanFacts(const sim::ContactReport& contacts, const sim::ObjectState& object_state,
                             const scenario::ObjectSpec& object, const Eigen::Isometry3d& hand_pose);

}  // namespace handover::human
