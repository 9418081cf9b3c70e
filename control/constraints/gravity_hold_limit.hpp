// Keeps the arm where it can hold itself up: gravity alone (payload included,
// Data::g) may take at most `share` of each joint's scaled torque limit, so
// the rest stays for motion and braking. Without it, torque limits too low
// for a far reach (limits.torque.scale, or a heavy object) let the tasks pull
// the arm out to where the torque rows can only let it sag: the QP turns
// infeasible against the table and the arm falls onto it.
//
// Per joint j, with L = share * scale * tau_max_j and phi = |g_j(q)|, a
// velocity damper (velocity_damper.hpp) on the distance d = L - phi, switched
// on below di = interaction * scale * tau_max_j; its rate is
// phi_dot = sign(g_j) G_j qdot with G = dg/dq (gravityJacobian), one row
// over qddot:  sign(g_j) G_j qddot <= -(damper's lower bound on d_ddot).
// A fast arm could come into the zone faster than its torque can stop it, so
// the rate toward the share is also held to what braking can stop:
// d_dot >= -sqrt(2 a d), a = |d_dot| / t with the stopping time t the
// largest joint momentum |(M qdot)_i| over the torque the share leaves,
// (1 - share) of the scaled limit (the gravity Jacobian every cycle).
// Like the position dampers it gives way to the variable bounds set before it
// (acceleration, position and velocity limits): the row's bound is raised to
// the least the bound box allows, so it never makes the QP infeasible with
// them (the object taken can put the arm inside the margin at once; it then
// leaves at the damper's recovery rate).
//
// Stateful (the damper's xi per joint); reset() forgets it. Real-time safe.
#pragma once

#include <array>
#include <string>

#include "control/formulation/constraint.hpp"

namespace handover::control {

struct GravityHoldParams {
  double share = 0.8;          ///< of the scaled torque limit, the most gravity may take
  double interaction = 0.1;    ///< of the scaled limit below share where the damper starts
  double damper_offset = 0.5;  ///< extra damping when the damper starts, fraction of the zone per s
  double recovery = 0.1;       ///< of the scaled limit per s, most the damper asks to regain
};

class GravityHoldLimit : public Constraint {
 public:
  /// Throws std::invalid_argument unless 0 < interaction < share <= 1 and the rest >= 0.
  GravityHoldLimit(const Model& model, double torque_scale, const GravityHoldParams& params = GravityHoldParams(),
                   std::string name = "gravity_hold");
  const std::string& name() const override { return name_; }
  int maxRows() const override { return kArmDofs; }
  int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd> chi_lb,
              Eigen::Ref<Eigen::VectorXd> chi_ub) override;
  void reset() { xi_.fill(0.0); }

 private:
  std::string name_;
  GravityHoldParams params_;
  Vector7 scaled_limit_;  ///< scale * tau_max, N m
  std::array<double, kArmDofs> xi_{};
  Matrix7 dg_dq_;         ///< this cycle's gravity Jacobian (scratch)
};

}  // namespace handover::control
