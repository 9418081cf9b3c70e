// The benchmark category of a scenario (docs/benchmark.md): the factors a
// handover is tabulated by. Every factor but the behaviour is derived from
// the scenario's own geometry, so a file written by hand is classified the
// same way as a generated one. Start-up / reporting only (not real-time safe).
#pragma once

#include <string>

#include "scenes/scenario/scenario.hpp"

namespace handover::scenario {

struct Category {
  std::string direction;  ///< take (human_to_robot) | give (robot_to_human)
  std::string grasp;      ///< top | angled | side | below | around_axis (see graspFamily)
  std::string shape;      ///< cylinder | box | sphere
  std::string behaviour;  ///< the scenario's `behaviour:` word, "file" when not given
  std::string placement;  ///< front | offset | side: where the person stands (see standPlacement)
  std::string hand;       ///< right | left
  std::string height;     ///< low (< 0.20 m) | mid (< 0.40 m) | high: handover location above the table
};

/// All factors of `s`.
Category categoryOf(const Scenario& s);

/// "direction/grasp/shape/behaviour", e.g. "take/side/cylinder/retry".
std::string categoryLabel(const Category& c);

/// Grasp family from the gripper's approach axis a (grasp frame z) against the
/// object's "up" u as the object is presented: u is the object's own axis
/// nearest to the world's vertical at the person's presentation pose (take), or
/// the object's z (give: the robot holds it). `around_axis` when the object declares a free axis
/// lying within 30 deg of horizontal and a is within 15 deg of perpendicular to
/// it; otherwise by the angle between a and -u: top < 22.5 deg, angled < 67.5,
/// side < 112.5, below beyond.
std::string graspFamily(const ObjectSpec& object, const Eigen::Vector3d& up_in_object);

/// The hand pose (world) when the person presents: before the first wait,
/// release or grasp step, after the reaches that precede it.
Eigen::Isometry3d presentationHandPose(const HumanSpec& human);

/// front: beyond the table's far edge (x >= 0.80 m) within 0.15 m of the
/// robot's axis line; offset: beyond the far edge, farther sideways; side:
/// beside the table.
std::string standPlacement(const Eigen::Vector2d& stand_xy);

}  // namespace handover::scenario
