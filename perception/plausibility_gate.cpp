#include "perception/plausibility_gate.hpp"

namespace handover::perception {

PlausibilityGate::PlausibilityGate(const GateSettings& settings) : settings_(settings) {}

bool PlausibilityGate::inBox(const Eigen::Vector3d& p) const {
  // written so that NaN fails too
  return (p.array() >= settings_.workspace_min.array()).all() && (p.array() <= settings_.workspace_max.array()).all();
}

bool PlausibilityGate::inWorkspace(const PoseSample& s) const {
  return inBox(s.hand.position) && inBox(s.forearm.position) && inBox(s.upper_arm.position) &&
         (!s.has_object || inBox(s.object.position));
}

RejectReason PlausibilityGate::judgeMove(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double dt,
                                         bool have_pred, const Eigen::Vector3d& pred) const {
  const double d = (to - from).norm();
  if (d > settings_.max_jump) return RejectReason::kJump;
  if (d > settings_.max_speed * dt + settings_.tolerance) return RejectReason::kSpeed;
  if (have_pred && (to - pred).norm() > 0.5 * settings_.max_acceleration * dt * dt + settings_.tolerance)
    return RejectReason::kAcceleration;
  return RejectReason::kCount;
}

GateResult PlausibilityGate::check(const PoseSample& s, const BodyPrediction& predicted) const {
  GateResult r;
  if (!inWorkspace(s)) {
    r.verdict = GateVerdict::kReject;
    r.reason = RejectReason::kWorkspace;
    return r;
  }
  const double dt = s.stamp - ref_.stamp;
  if (!have_ || dt > settings_.reseed_gap) {
    r.verdict = GateVerdict::kReseed;
    return r;
  }
  const bool p = predicted.valid;
  RejectReason why = judgeMove(ref_.hand.position, s.hand.position, dt, p, predicted.hand);
  if (why == RejectReason::kCount) why = judgeMove(ref_.forearm.position, s.forearm.position, dt, p, predicted.forearm);
  if (why == RejectReason::kCount)
    why = judgeMove(ref_.upper_arm.position, s.upper_arm.position, dt, p, predicted.upper_arm);
  if (why == RejectReason::kCount && s.has_object && ref_.has_object)
    why = judgeMove(ref_.object.position, s.object.position, dt, p && predicted.has_object, predicted.object);
  if (why != RejectReason::kCount) {
    r.verdict = GateVerdict::kReject;
    r.reason = why;
  }
  return r;
}

void PlausibilityGate::accept(const PoseSample& s) {
  ref_ = s;
  have_ = true;
}

}  // namespace handover::perception
