// Places the upper arm and forearm of the simulated person: a two-link arm
// from the shoulder to the grip point, the hand continuing the forearm's line
// (wrist on the elbow->grip segment). The elbow sits on the circle of
// solutions at the point nearest a preferred direction (down and outward, as
// people hold their elbows), so the links stand where a real arm would.
// World frame, m. Real-time safe (no allocation).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace handover::human {

struct ArmLengths {
  double upper_arm = 0.36;      ///< shoulder to elbow, m
  double forearm = 0.28;        ///< elbow to wrist, m
  double wrist_to_grip = 0.075; ///< wrist to grip point, m
};

struct ArmPlacement {
  Eigen::Vector3d shoulder = Eigen::Vector3d::Zero();
  Eigen::Vector3d elbow = Eigen::Vector3d::Zero();
  Eigen::Vector3d wrist = Eigen::Vector3d::Zero();
  Eigen::Vector3d grip = Eigen::Vector3d::Zero();  ///< where the arm's grip point ends up
  /// origin at the shoulder, z along shoulder->elbow, x normal to the arm's plane
  Eigen::Isometry3d upper_arm = Eigen::Isometry3d::Identity();
  /// origin at the elbow, z along elbow->wrist, x as the upper arm's
  Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();
  bool reached = true;  ///< false when the target was out of reach (arm straight toward it)
};

/// Solves the arm for a grip-point target. `elbow_hint` (any length > 0)
/// points where the elbow should rather go, e.g. down and outward.
ArmPlacement placeArm(const Eigen::Vector3d& shoulder, const Eigen::Vector3d& grip_target,
                      const ArmLengths& lengths, const Eigen::Vector3d& elbow_hint);

}  // namespace handover::human
