#include "control/tasks/trajectory_tracking_task.hpp"

#include <algorithm>

#include "control/so3.hpp"

namespace handover::control {

namespace {
/// The error a PD acts on, clipped so that it asks at most `max_speed`
/// (K |e| <= D max_speed); unchanged without a limit.
Vector3 speedLimited(const Vector3& e, const PdGains& g, double max_speed) {
  if (max_speed <= 0.0 || g.stiffness <= 0.0) return e;
  const double limit = g.damping * max_speed / g.stiffness;
  const double n = e.norm();
  return n > limit ? Vector3(e * (limit / n)) : e;
}
}  // namespace

TrajectoryTrackingTask::TrajectoryTrackingTask(const Model& model, std::string name, const std::string& frame,
                                               PdGains translation, PdGains orientation)
    : name_(std::move(name)), frame_id_(model.frameId(frame)), translation_(translation), orientation_(orientation),
      configured_translation_(translation), configured_orientation_(orientation) {}

bool TrajectoryTrackingTask::applyGains(const TaskGains& gains) {
  if (gains.configured) setGains(configured_translation_, configured_orientation_);
  else setGains(gains.translation, gains.orientation);
  // a phase may close in slower than the configured limit (never faster)
  max_speed_ = configured_max_speed_;
  if (!gains.configured && gains.max_speed > 0.0)
    max_speed_ = configured_max_speed_ > 0.0 ? std::min(configured_max_speed_, gains.max_speed) : gains.max_speed;
  return true;
}

void TrajectoryTrackingTask::setGains(const PdGains& translation, const PdGains& orientation) {
  translation_ = translation;
  orientation_ = orientation;
}

void TrajectoryTrackingTask::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A,
                                     Eigen::Ref<Eigen::VectorXd> b) {
  const Model& model = *ctx.model;
  const Data& data = *ctx.data;
  const ObservedState& obs = ctx.observed;

  // end effector, computed once per cycle by computeAll
  const Isometry X_ee = framePlacement(model, data, frame_id_);
  frameJacobian(model, data, frame_id_, J_);
  const Vector6 v_ee = J_ * data.v;
  const Vector6 drift = frameDrift(model, data, frame_id_);
  const Matrix3& R_ee = X_ee.linear();

  // grasp frame with zero object acceleration: its acceleration is then the
  // velocity-product term w x (w x r); the rest is in the alphadot_obs columns
  // the wrist joint's angle from the middle of its range picks a parallel-gripper twin
  const double wrist = data.q[kArmDofs - 1] - 0.5 * (model.q_min[kArmDofs - 1] + model.q_max[kArmDofs - 1]);
  const GraspFrameState g = graspFrameState(obs, Vector6::Zero(), offset_, R_ee, wrist);
  const Vector3& r = g.lever;
  const Vector3 w_obs = obs.velocity.tail<3>();
  const Vector3 w_ee = v_ee.tail<3>();

  // translation rows
  error_.head<3>() = X_ee.translation() - g.pose.translation();
  const Vector3 edot_p = v_ee.head<3>() - g.velocity.head<3>();
  A.block<3, kArmDofs>(0, VariableLayout::kQdd) = J_.topRows<3>();
  A.block<3, 3>(0, VariableLayout::kObs) = -Matrix3::Identity();
  A.block<3, 3>(0, VariableLayout::kObs + 3) = skew(r);
  b.head<3>() = -translation_.stiffness * speedLimited(error_.head<3>(), translation_, max_speed_) -
                translation_.damping * edot_p - drift.head<3>() +
                g.acceleration.head<3>();

  // orientation rows
  angle_error_ = logRotation(R_ee * g.pose.linear().transpose()).norm();
  // full orientation rows unless the rotation about a free axis is left free
  if (!offset_.has_free_axis || offset_.approach_from_base) {
    if (offset_.has_joint_plan) {
      Quaternion now(R_ee);
      const Quaternion plan = lift_.plan(model, frame_id_, data.q, now, offset_.joint_plan);
      error_.tail<3>() = plannedTurnError(now, Quaternion(g.pose.linear()), plan, long_way_);
    } else {
      error_.tail<3>() = orientationError(R_ee, g.pose.linear());
      long_way_ = false;
      lift_.reset();
    }
    A.block<3, kArmDofs>(3, VariableLayout::kQdd) = J_.bottomRows<3>();
    A.block<3, 3>(3, VariableLayout::kObs + 3) = -Matrix3::Identity();
    b.tail<3>() = -orientation_.stiffness * speedLimited(error_.tail<3>(), orientation_, max_angular_speed_) -
                  orientation_.damping * (w_ee - w_obs) -
                  drift.tail<3>();
    return;
  }
  const Vector3 u = offset_.placement.linear().transpose() * offset_.free_axis;
  const Vector3 a = obs.pose.linear() * offset_.free_axis;
  const Vector3 bv = R_ee * u;
  const Vector3 c = bv - a;
  const Vector3 cdot = w_ee.cross(bv) - w_obs.cross(a);
  error_.tail<3>() = c;
  const Matrix3 P = Matrix3::Identity() - bv * bv.transpose();
  const Matrix3 Sb = skew(bv);
  A.block<3, kArmDofs>(3, VariableLayout::kQdd) = -Sb * J_.bottomRows<3>();
  A.block<3, 3>(3, VariableLayout::kObs + 3) = P * skew(a);
  b.tail<3>() = P * (-orientation_.stiffness * speedLimited(c, orientation_, max_angular_speed_) - orientation_.damping * cdot + Sb * drift.tail<3>() -
                     w_ee.cross(w_ee.cross(bv)) + w_obs.cross(w_obs.cross(a)));
}

}  // namespace handover::control
