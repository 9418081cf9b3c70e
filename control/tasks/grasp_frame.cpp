#include "control/tasks/grasp_frame.hpp"

#include "control/so3.hpp"

namespace handover::control {

Matrix3 graspRotation(const ObservedState& obs, const GraspOffset& offset, const Matrix3& R_ee) {
  const Matrix3& R_obs = obs.pose.linear();
  const Matrix3& R_go = offset.placement.linear();
  if (!offset.has_free_axis) return R_obs * R_go;
  // the axis as seen by the gripper (u, grasp frame) and by the object (a, world)
  const Vector3 u = R_go.transpose() * offset.free_axis;
  const Vector3 a = R_obs * offset.free_axis;
  const Vector3 b = R_ee * u;
  const Quaternion q_min = Quaternion::FromTwoVectors(b, a);
  return q_min.toRotationMatrix() * R_ee;
}

GraspFrameState graspFrameState(const ObservedState& obs, const Vector6& alphadot_obs, const GraspOffset& offset,
                                const Matrix3& R_ee) {
  GraspFrameState s;
  const Matrix3 R_g = graspRotation(obs, offset, R_ee);
  // R_obs * Rot(phi) = R_g R_grasp^obs' carries the grasp point with the chosen grasp
  const Vector3 r = R_g * offset.placement.linear().transpose() * offset.placement.translation();
  const Vector3 w = obs.velocity.tail<3>();
  const Vector3 wdot = alphadot_obs.tail<3>();
  s.pose.linear() = R_g;
  s.pose.translation() = obs.pose.translation() + r;
  s.velocity.head<3>() = obs.velocity.head<3>() + w.cross(r);
  s.velocity.tail<3>() = w;
  s.acceleration.head<3>() = alphadot_obs.head<3>() + wdot.cross(r) + w.cross(w.cross(r));
  s.acceleration.tail<3>() = wdot;
  s.lever = r;
  return s;
}

}  // namespace handover::control
