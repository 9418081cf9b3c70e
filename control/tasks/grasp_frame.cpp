#include "control/tasks/grasp_frame.hpp"

#include <cmath>

#include "control/so3.hpp"

namespace handover::control {

Matrix3 graspRotation(const ObservedState& obs, const GraspOffset& offset, const Matrix3& R_ee) {
  const Matrix3& R_obs = obs.pose.linear();
  const Matrix3& R_go = offset.placement.linear();
  if (!offset.has_free_axis) return R_obs * R_go;
  if (offset.approach_from_base) {
    // phi maximises  d . z(phi) + kappa tr(R_ee' Rot(a, phi) R0):  the approach
    // axis z(phi) facing away from the base (d: base-to-object direction
    // across the axis, unit) plus a little of "nearest to the gripper", which
    // alone decides when the approach runs along the axis (z0 || a). Both
    // terms are A cos(phi) + B sin(phi) + const, so phi is closed form.
    constexpr double kappa = 0.25;
    const Vector3 a = (R_obs * offset.free_axis).normalized();
    const Matrix3 R0 = R_obs * R_go;
    const Vector3 z0 = R0.col(2);
    const Vector3 d = obs.pose.translation() - offset.base;
    Vector3 d_perp = d - a.dot(d) * a;
    d_perp = d_perp.norm() > 1e-9 ? Vector3(d_perp.normalized()) : Vector3::Zero();
    const Matrix3 M = R0 * R_ee.transpose();
    const double A = d_perp.dot(z0 - a.dot(z0) * a) + kappa * (M.trace() - a.dot(M * a));
    const double B = d_perp.dot(a.cross(z0)) + kappa * (skew(a) * M).trace();
    const double phi = std::atan2(B, A);
    return Eigen::AngleAxisd(phi, a).toRotationMatrix() * R0;
  }
  // the axis as seen by the gripper (u, grasp frame) and by the object (a, world)
  const Vector3 u = R_go.transpose() * offset.free_axis;
  const Vector3 a = R_obs * offset.free_axis;
  const Vector3 b = R_ee * u;
  const Quaternion q_min = Quaternion::FromTwoVectors(b, a);
  return q_min.toRotationMatrix() * R_ee;
}

GraspFrameState graspFrameState(const ObservedState& obs, const Vector6& alphadot_obs, const GraspOffset& offset,
                                const Matrix3& R_ee, double wrist_angle) {
  GraspFrameState s;
  const Matrix3 R_g = graspRotation(obs, offset, R_ee);
  // R_obs * Rot(phi) = R_g R_grasp^obs' carries the grasp point with the chosen grasp
  const Vector3 r = R_g * offset.placement.linear().transpose() * offset.placement.translation();
  const Vector3 w = obs.velocity.tail<3>();
  const Vector3 wdot = alphadot_obs.tail<3>();
  // the half-turned twin of a parallel-jaw grasp: the one whose turn phi
  // about the tool axis leaves the wrist joint (at wrist_angle from its
  // middle) nearest the middle; wrist_angle + phi is the joint's goal, which
  // moving toward either twin does not change, so the choice cannot chatter
  bool twin = false;
  if (offset.parallel_gripper) {
    const Matrix3 R_rel = R_ee.transpose() * R_g;
    const double phi = std::atan2(R_rel(1, 0) - R_rel(0, 1), R_rel(0, 0) + R_rel(1, 1));
    const double phi_twin = phi > 0.0 ? phi - M_PI : phi + M_PI;
    twin = std::abs(wrist_angle + phi_twin) < std::abs(wrist_angle + phi);
  }
  s.pose.linear() = twin ? Matrix3(R_g * Eigen::AngleAxisd(M_PI, Vector3::UnitZ()).toRotationMatrix()) : R_g;
  s.pose.translation() = obs.pose.translation() + r;
  s.velocity.head<3>() = obs.velocity.head<3>() + w.cross(r);
  s.velocity.tail<3>() = w;
  s.acceleration.head<3>() = alphadot_obs.head<3>() + wdot.cross(r) + w.cross(w.cross(r));
  s.acceleration.tail<3>() = wdot;
  // the placement slides along the grasp's approach axis (the standoff changing): in the
  // object's turning frame, d/dt (R z s) = w x (R z s) + R z sdot
  if (offset.approach_speed != 0.0 || offset.approach_acceleration != 0.0) {
    const Vector3 z = s.pose.linear().col(2);
    const Vector3 slide = offset.approach_speed * z;
    s.velocity.head<3>() += slide;
    s.acceleration.head<3>() += offset.approach_acceleration * z + 2.0 * w.cross(slide);
  }
  s.lever = r;
  return s;
}

}  // namespace handover::control
