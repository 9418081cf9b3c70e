// One measurement of the person's arm: hand (grip point frame), forearm and
// upper arm, world frame (design notes 1). Positions in m, orientations as
// unit quaternions (stored as such so that logs round-trip exactly).
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <Eigen/Geometry>

#include "interfaces/human_body_poses.hpp"

namespace handover::perception {

/// A rigid pose: position (m, world) and orientation (unit quaternion, body to world).
struct Pose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();

  Eigen::Isometry3d isometry() const {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = orientation.toRotationMatrix();
    T.translation() = position;
    return T;
  }
  static Pose fromIsometry(const Eigen::Isometry3d& T) {
    Pose p;
    p.position = T.translation();
    p.orientation = Eigen::Quaterniond(T.rotation()).normalized();
    return p;
  }
  bool allFinite() const { return position.allFinite() && orientation.coeffs().allFinite(); }
};

/// A timestamped sample of the three tracked bodies, and of the object when
/// the tracker follows it as its own rigid body.
struct PoseSample {
  double stamp = 0.0;  ///< s, time the poses were measured, on the controller's clock
  Pose hand;           ///< grip point frame
  Pose forearm;        ///< origin at the elbow, z along elbow->wrist
  Pose upper_arm;      ///< origin at the shoulder, z along shoulder->elbow
  bool has_object = false;  ///< `object` was measured (else the object is hand * offset)
  Pose object;              ///< object frame (the scenario's object frame), world

  bool allFinite() const {
    return std::isfinite(stamp) && hand.allFinite() && forearm.allFinite() && upper_arm.allFinite() &&
           (!has_object || object.allFinite());
  }
};

/// The three tracked bodies of a simulator pose set, as a sample at `stamp`.
inline PoseSample sampleFromBodies(double stamp, const io::HumanBodyPoses& b) {
  PoseSample s;
  s.stamp = stamp;
  s.hand = Pose::fromIsometry(b.hand);
  s.forearm = Pose::fromIsometry(b.forearm);
  s.upper_arm = Pose::fromIsometry(b.upper_arm);
  return s;
}

}  // namespace handover::perception
