#include "control/tasks/planned_turn.hpp"

#include <algorithm>
#include <cmath>

#include "control/model/algorithms.hpp"

namespace handover::control {

Quaternion planOrientationAlongJointPath(const Model& model, int frame_id, const Vector7& q, const Quaternion& now,
                                         const Vector7& q_plan) {
  const Vector7 dq = q_plan - q;
  // |omega| <= sum |qdot_i| (unit axes): a step of summed motion <= pi / 2
  // turns the frame <= pi / 2, half that between the quaternions
  const int steps = std::max(1, static_cast<int>(std::ceil(dq.cwiseAbs().sum() / (0.5 * M_PI))));
  Quaternion lifted = now.normalized();
  for (int k = 1; k <= steps; ++k) {
    Quaternion next(frameRotation(model, frame_id, q + dq * (static_cast<double>(k) / steps)));
    next.normalize();
    if (next.dot(lifted) < 0.0) next.coeffs() = -next.coeffs();
    lifted = next;
  }
  return lifted;
}

Quaternion PlannedTurnLift::plan(const Model& model, int frame_id, const Vector7& q, Quaternion& now,
                                 const Vector7& q_plan) {
  const bool continuous = valid_ && q_plan == q_plan_ && (q - q_).cwiseAbs().sum() <= 0.5 * M_PI;
  if (continuous) {
    if (now.dot(now_) < 0.0) now.coeffs() = -now.coeffs();
  } else {
    plan_ = planOrientationAlongJointPath(model, frame_id, q, now, q_plan);
    q_plan_ = q_plan;
    valid_ = true;
  }
  q_ = q;
  now_ = now;
  return plan_;
}

Vector3 plannedTurnError(const Quaternion& now, const Quaternion& target, const Quaternion& plan, bool& long_way) {
  Quaternion t = target;
  const double agree = t.dot(plan);  // cos of half the angle between plan and target
  const double short_angle = 2.0 * std::acos(std::min(1.0, std::abs(t.dot(now))));
  if (std::abs(agree) >= std::cos(0.25 * M_PI) && short_angle >= kDefinedAxis) {
    if (agree < 0.0) t.coeffs() = -t.coeffs();
    long_way = t.dot(now) < 0.0;
  } else if (short_angle < kDefinedAxis) {
    long_way = false;
  }
  // the sign of the target that gives the chosen way
  if ((t.dot(now) < 0.0) != long_way) t.coeffs() = -t.coeffs();
  const Quaternion e = now * t.conjugate();  // R_now R_target^T
  const double n = e.vec().norm();
  if (n < 1e-12) return 2.0 * e.vec();
  return (2.0 * std::atan2(n, e.w()) / n) * e.vec();
}

}  // namespace handover::control
