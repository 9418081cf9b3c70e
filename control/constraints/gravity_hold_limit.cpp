#include "control/constraints/gravity_hold_limit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "control/constraints/velocity_damper.hpp"

namespace handover::control {

GravityHoldLimit::GravityHoldLimit(const Model& model, double torque_scale, const GravityHoldParams& params,
                                   std::string name)
    : name_(std::move(name)), params_(params), scaled_limit_(torque_scale * model.tau_max) {
  if (!(params.interaction > 0.0 && params.interaction < params.share && params.share <= 1.0))
    throw std::invalid_argument("GravityHoldLimit '" + name_ + "': need 0 < interaction < share <= 1");
  if (!(params.damper_offset >= 0.0) || !(params.recovery >= 0.0))
    throw std::invalid_argument("GravityHoldLimit '" + name_ + "': negative damper_offset or recovery");
  reset();
}

int GravityHoldLimit::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C,
                              Eigen::Ref<Eigen::VectorXd> lb, Eigen::Ref<Eigen::VectorXd> ub,
                              Eigen::Ref<Eigen::VectorXd> chi_lb, Eigen::Ref<Eigen::VectorXd> chi_ub) {
  const Data& data = *ctx.data;
  gravityJacobian(*ctx.model, data, dg_dq_);
  // The time the arm needs to stop from its present motion with the torque the
  // share leaves (1 - share of each scaled limit), braking along its own
  // motion: the largest joint momentum over its reserve.
  double stop_time = 0.0;
  for (int i = 0; i < kArmDofs; ++i) {
    const double reserve = (1.0 - params_.share) * scaled_limit_[i];
    const double momentum = std::abs(data.M.row(i).dot(data.v));
    stop_time = std::max(stop_time, reserve > 0.0 ? momentum / reserve : 0.0);
  }
  int rows = 0;
  for (int j = 0; j < kArmDofs; ++j) {
    const double limit = params_.share * scaled_limit_[j];
    const double di = params_.interaction * scaled_limit_[j];
    const double d = limit - std::abs(data.g[j]);
    const double sign = data.g[j] >= 0.0 ? 1.0 : -1.0;
    // d_dot = -phi_dot = -sign G_j qdot (the G_dot qdot term is second order here)
    const double d_dot = -sign * dg_dq_.row(j).dot(data.v);
    // Braking: d falls at |d_dot| and the arm stops within stop_time, so d
    // can fall at most as fast as braking at a = |d_dot| / stop_time lets it
    // still stop before the share: d_dot >= -sqrt(2 a d). Without it a fast
    // arm enters the damper's zone faster than its torque can stop it.
    double braking = -std::numeric_limits<double>::infinity();
    if (d_dot < 0.0 && stop_time > 0.0) {
      const double deceleration = -d_dot / stop_time;
      const double v_min = -std::sqrt(2.0 * deceleration * std::max(d, 0.0));
      if (d_dot < 0.5 * v_min) braking = (v_min - d_dot) / ctx.dt;  // within 4x its stopping distance
    }
    double damper = -std::numeric_limits<double>::infinity();
    if (d < di) {
      damper = velocityDamperBound(d, d_dot, di, 0.0, params_.damper_offset, params_.recovery * scaled_limit_[j],
                                   ctx.dt, xi_[j]);
    } else {
      xi_[j] = 0.0;
    }
    const double d_ddot_min = std::max(damper, braking);
    if (!std::isfinite(d_ddot_min)) continue;
    // row: sign G_j qddot <= -d_ddot_min, never below what the bound box allows
    double reachable = 0.0;  // min of the row over chi_lb <= qddot <= chi_ub
    for (int i = 0; i < kArmDofs; ++i) {
      const double c = sign * dg_dq_(j, i);
      C(rows, VariableLayout::kQdd + i) = c;
      if (c == 0.0) continue;  // (0 * an open bound is no number)
      reachable += std::min(c * chi_lb[VariableLayout::kQdd + i], c * chi_ub[VariableLayout::kQdd + i]);
    }
    lb[rows] = -std::numeric_limits<double>::infinity();
    ub[rows] = std::isfinite(reachable) ? std::max(-d_ddot_min, reachable + 1e-9 * (1.0 + std::abs(reachable)))
                                        : -d_ddot_min;
    ++rows;
  }
  return rows;
}

}  // namespace handover::control
