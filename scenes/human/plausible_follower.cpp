#include "scenes/human/plausible_follower.hpp"

#include <algorithm>
#include <cmath>

#include "config/input_error.hpp"

namespace handover::human {

namespace {

Eigen::Vector3d clampNorm(const Eigen::Vector3d& v, double max) {
  const double n = v.norm();
  return n > max ? Eigen::Vector3d(v * (max / n)) : v;
}

}  // namespace

PlausibleFollower::PlausibleFollower(const HandMotionLimits& limits, double dt) : limits_(limits), dt_(dt) {
  if (!(dt > 0.0) || !(limits.max_speed > 0.0) || !(limits.max_acceleration > 0.0) ||
      !(limits.max_angular_speed > 0.0)) {
    throw InputError("PlausibleFollower: the period and the hand's limits must be > 0");
  }
}

void PlausibleFollower::reset(const sim::HumanBodyPoses& poses) {
  out_ = poses;
  const Eigen::Isometry3d* x[3] = {&poses.hand, &poses.forearm, &poses.upper_arm};
  for (int i = 0; i < 3; ++i) {
    Body& b = bodies_[i];
    b.pos = b.target_prev = x[i]->translation();
    b.vel.setZero();
    b.rot = Eigen::Quaterniond(x[i]->linear()).normalized();
    b.following = false;
  }
  slowed_steps_ = 0;
  largest_gap_ = 0.0;
}

bool PlausibleFollower::follow(Body& b, const Eigen::Isometry3d& target, Eigen::Isometry3d& out) {
  const Eigen::Vector3d tp = target.translation();
  const Eigen::Quaterniond tq = Eigen::Quaterniond(target.linear()).normalized();
  const Eigen::Vector3d v_target = clampNorm((tp - b.target_prev) / dt_, limits_.max_speed);
  b.target_prev = tp;
  const double max_step = limits_.max_speed * dt_;
  const double max_turn = limits_.max_angular_speed * dt_;
  if (!b.following) {
    if ((tp - b.pos).norm() <= max_step && b.rot.angularDistance(tq) <= max_turn) {
      // a hand can do this: pass the target through
      b.vel = clampNorm((tp - b.pos) / dt_, limits_.max_speed);
      b.pos = tp;
      b.rot = tq;
      out = target;
      return false;
    }
    b.following = true;  // from the velocity it had
  }
  const Eigen::Vector3d e = tp - b.pos;
  const double d = e.norm();
  largest_gap_ = std::max(largest_gap_, d);
  const double angle = b.rot.angularDistance(tq);
  // lands on the target this step within the limits: caught up, back to passing through
  const Eigen::Vector3d v_land = e / dt_;
  const double dv_max = limits_.max_acceleration * dt_ * (1.0 + 1e-9);
  if (v_land.norm() <= limits_.max_speed && (v_land - b.vel).norm() <= dv_max &&
      (v_land - v_target).norm() <= dv_max && angle <= max_turn) {
    b.following = false;
    b.vel = v_land;
    b.pos = tp;
    b.rot = tq;
    out = target;
    return false;
  }
  // close the gap at the target's own (plausible) velocity plus the largest
  // speed from which, after one more step, braking at max_acceleration still
  // stops at the target (v dt + v^2 / (2 a) <= d: no overshoot in discrete time)
  const double a = limits_.max_acceleration;
  Eigen::Vector3d v_des = v_target;
  if (d > 0.0) {
    const double brake = -a * dt_ + std::sqrt(a * dt_ * a * dt_ + 2.0 * a * d);
    v_des += e / d * std::min(limits_.max_speed, brake);
  }
  v_des = clampNorm(v_des, limits_.max_speed);
  b.vel += clampNorm(v_des - b.vel, limits_.max_acceleration * dt_);
  b.pos += b.vel * dt_;
  if (angle > max_turn) b.rot = b.rot.slerp(max_turn / angle, tq).normalized();
  else b.rot = tq;
  out = Eigen::Isometry3d::Identity();
  out.linear() = b.rot.toRotationMatrix();
  out.translation() = b.pos;
  return true;
}

const sim::HumanBodyPoses& PlausibleFollower::step(const sim::HumanBodyPoses& target) {
  const sim::HumanBodyPoses in = target;  // `target` may alias the output
  out_ = in;
  follow(bodies_[0], in.hand, out_.hand);
  follow(bodies_[1], in.forearm, out_.forearm);
  follow(bodies_[2], in.upper_arm, out_.upper_arm);
  const double gap = std::max({(in.hand.translation() - out_.hand.translation()).norm(),
                               (in.forearm.translation() - out_.forearm.translation()).norm(),
                               (in.upper_arm.translation() - out_.upper_arm.translation()).norm()});
  if (gap > kReportedGap) ++slowed_steps_;
  return out_;
}

}  // namespace handover::human
