#include "control/safety/limit_guard.hpp"

#include <algorithm>
#include <cmath>

namespace handover::control {

LimitGuardSettings parseLimitGuardSettings(const YamlReader& s) {
  LimitGuardSettings g;
  if (!s.isMap()) s.fail("expected a map with position_margin, velocity_scale, deceleration_scale, torque_scale");
  if (auto c = s.optionalChild("position_margin")) g.position_margin = c->checkRange(c->asDouble(), 0.0, 0.1);
  if (auto c = s.optionalChild("velocity_scale")) g.velocity_scale = c->checkRange(c->asDouble(), 0.01, 1.0);
  if (auto c = s.optionalChild("deceleration_scale")) g.deceleration_scale = c->checkRange(c->asDouble(), 0.01, 1.0);
  if (auto c = s.optionalChild("torque_scale")) g.torque_scale = c->checkRange(c->asDouble(), 0.01, 1.0);
  s.finish();
  return g;
}

LimitGuard::LimitGuard(const Model& model, const LimitGuardSettings& settings, double period)
    : settings_(settings), dt_(period) {
  const Vector7 margin = Vector7::Constant(settings.position_margin);
  // a margin wider than half a joint's range would cross the limits: keep the middle
  const Vector7 mid = 0.5 * (model.q_min + model.q_max);
  q_min_ = (model.q_min + margin).cwiseMin(mid);
  q_max_ = (model.q_max - margin).cwiseMax(mid);
  v_max_ = settings.velocity_scale * model.v_max;
  a_brake_ = settings.deceleration_scale * model.a_max;
  tau_max_ = settings.torque_scale * model.tau_max;
  projection_.reserve(kArmDofs, 0, kArmDofs);
  projection_.n_in = kArmDofs;
  projection_.H.setIdentity();
  solver_.reserve(kArmDofs, 0, kArmDofs);
  x_ = Eigen::VectorXd::Zero(kArmDofs);
  reset();
}

void LimitGuard::reset() {
  changed_count_ = 0;
  last_changed_ = false;
  lo_.setZero();
  hi_.setZero();
}

double LimitGuard::stoppingSpeed(int i, double d) const {
  if (!(d > 0.0)) return 0.0;
  // after this period the joint has moved dt v+; from there braking at a
  // covers v+^2 / (2 a): dt v+ + v+^2 / (2 a) <= d
  const double a = a_brake_[i];
  const double adt = a * dt_;
  return -adt + std::sqrt(adt * adt + 2.0 * a * d);
}

bool LimitGuard::apply(const Data& data, const Vector7& tau_external, Vector7& qdd, Vector7& tau,
                       const Vector7& tau_unmodelled) {
  const Vector7& q = data.q;
  const Vector7& qd = data.v;

  // what a torque the model misses adds to the commanded acceleration: a
  // person pressing on the gripper or the held object turns the light wrist
  // joints faster than any command (a 0.5 N m push spun joint 7 past its
  // limit in 45 ms while the QP, blind to it, commanded almost nothing)
  bool factored = false;  // llt_ holds M
  Vector7 a_unmodelled = Vector7::Zero();
  if (tau_unmodelled.allFinite() && !tau_unmodelled.isZero(0.0)) {
    llt_.compute(data.M);
    factored = true;
    a_unmodelled = llt_.solve(tau_unmodelled);
  }

  // the braking box on qdd from the position and velocity limits
  bool changed = false;
  for (int i = 0; i < kArmDofs; ++i) {
    const double v_up = std::min(v_max_[i], stoppingSpeed(i, q_max_[i] - q[i]));
    const double v_lo = std::max(-v_max_[i], -stoppingSpeed(i, q[i] - q_min_[i]));
    lo_[i] = (v_lo - qd[i]) / dt_ - a_unmodelled[i];
    hi_[i] = (v_up - qd[i]) / dt_ - a_unmodelled[i];
    double a = qdd[i];
    if (!std::isfinite(a)) a = std::clamp(0.0, lo_[i], hi_[i]);
    a = std::clamp(a, lo_[i], hi_[i]);
    changed |= !(a == qdd[i]);
    qdd[i] = a;
  }

  // the torque it takes, within the torque limits
  const Vector7 bias = data.h - tau_external;
  tau.noalias() = data.M * qdd;
  tau += bias;
  auto within = [&](const Vector7& t) { return ((t.cwiseAbs() - tau_max_).array() <= 0.0).all(); };
  if (!within(tau)) {
    changed = true;
    // the nearest acceleration in the box whose torque is within the limits
    projection_.g = -qdd;
    projection_.C.topRows<kArmDofs>() = data.M;
    projection_.c_lb.head<kArmDofs>() = -tau_max_ - bias;
    projection_.c_ub.head<kArmDofs>() = tau_max_ - bias;
    projection_.x_lb = lo_;
    projection_.x_ub = hi_;
    solver_.resetWarmStart();
    if (solver_.solve(projection_, x_) == QpStatus::kOptimal && x_.allFinite()) {
      qdd = x_;
      tau.noalias() = data.M * qdd;
      tau += bias;
    }
    // within the solver's tolerance: a last clamp of a few ulps leaves qdd as solved
    const auto nearly = [&](const Vector7& t) {
      return ((t.cwiseAbs() - tau_max_ * (1.0 + 1e-9)).array() <= 0.0).all();
    };
    if (!nearly(tau)) {
      if (!factored) llt_.compute(data.M);
      for (int round = 0; round < kTorqueRounds && !nearly(tau); ++round) {
        tau = tau.cwiseMax(-tau_max_).cwiseMin(tau_max_);
        qdd = llt_.solve(tau - bias);  // what that torque does
        qdd = qdd.cwiseMax(lo_).cwiseMin(hi_);
        tau.noalias() = data.M * qdd;
        tau += bias;
      }
      if (!nearly(tau)) {
        // the box is out of the torque's reach: the torque limit holds regardless
        tau = tau.cwiseMax(-tau_max_).cwiseMin(tau_max_);
        qdd = llt_.solve(tau - bias);
      }
    }
    tau = tau.cwiseMax(-tau_max_).cwiseMin(tau_max_);
  }

  // non-finite model terms (never expected): no torque rather than a wild one
  for (int i = 0; i < kArmDofs; ++i) {
    if (!std::isfinite(tau[i])) {
      tau[i] = 0.0;
      qdd[i] = 0.0;
      changed = true;
    }
  }

  last_changed_ = changed;
  if (changed) ++changed_count_;
  return changed;
}

}  // namespace handover::control
