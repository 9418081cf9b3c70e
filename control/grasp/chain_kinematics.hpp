// Lean forward kinematics for inverse kinematics: body poses and one frame's
// pose and Jacobian, nothing else (no velocities, drifts or mass properties,
// which control::forwardKinematics also computes for the control cycle).
// An IK iteration needs only this, at about a third of the cost.
//
// Frames: world axes, base at the origin; Jacobian rows [linear velocity of
// the frame origin; angular velocity], world axes, as control::frameJacobian.
// Units: SI. Real-time safe: fixed-size storage, no allocation, no exceptions.
#pragma once

#include <array>

#include "control/model/model.hpp"

namespace handover::control::grasp {

/// World poses of the bodies and world joint axes at one configuration.
struct ChainPoses {
  std::array<Isometry, kNumBodies> oMb;     ///< body i's pose in the world (0 = base)
  std::array<Vector3, kNumBodies> axis;     ///< joint i's unit axis in world axes (index 0 unused)
};

/// Body poses at q (rad).
void chainPoses(const Model& model, const Vector7& q, ChainPoses& poses);

/// Pose of model frame `frame_id` after chainPoses.
Isometry chainFramePose(const Model& model, const ChainPoses& poses, int frame_id);

/// 6x7 Jacobian of model frame `frame_id` after chainPoses (columns of joints
/// that do not move the frame's body are zero).
void chainFrameJacobian(const Model& model, const ChainPoses& poses, int frame_id, Matrix6x7& J);

}  // namespace handover::control::grasp
