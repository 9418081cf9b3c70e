// Collision avoidance as velocity dampers at the acceleration level
// (mc_rtc style), one row per active pair over chi = [qddot (7); obs (6)].
//
// For a pair with distance d < iDist (d, d_dot, Jd, drift from
// updateCollisions), the row asks that after one control period
//   d_dot + dt * d_ddot >= -xi (d - sDist) / (iDist - sDist),
// with d_ddot = Jd qddot + drift, i.e.
//   Jd qddot >= (-xi (d - sDist) / (iDist - sDist) - d_dot) / dt - drift.
// The bound reaches 0 at d = sDist, so d never falls below sDist.
// Automatic damping (default): when a pair enters iDist, xi is chosen so the
// current d_dot is admissible, plus an offset; it stays until the pair leaves.
// A pair closing faster than the arm can give way within iDist (a person's
// hand reaching at 1 m/s) engages earlier: at sDist + d_dot^2 / escape (what
// the row may demand: max_escape, less where the arm cannot reach it),
// at most iDist + broadphase_margin; that distance then serves as its iDist
// until it leaves. Pairs not engaged give no row.
//
// Build: compiled into handover_collision (control/collision/CMakeLists.txt).
#pragma once

#include <string>
#include <vector>

#include "control/collision/collision_config.hpp"
#include "control/collision/collision_data.hpp"
#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_environment.hpp"
#include "control/collision/collision_model.hpp"
#include "control/formulation/constraint.hpp"

namespace handover::control {

/// Damper state of one pair (for logs and tests).
struct DamperState {
  bool inside = false;   ///< engaged (d < i_dist) at the last compute()
  double i_dist = 0.0;   ///< m, the interaction distance it engaged at (>= the rule's iDist)
  double xi = 0.0;       ///< m/s, damping in use
  double bound = 0.0;    ///< m/s, lower bound on d_dot at the next step
};

class CollisionConstraint : public Constraint {
 public:
  /// Builds the collision scene (allocates; start-up). Throws InputError on a
  /// config that does not fit the model.
  CollisionConstraint(const Model& model, const CollisionConfig& config, std::string name = "collision");

  const std::string& name() const override { return name_; }
  int maxRows() const override { return cmodel_.numPairs(); }
  /// Soft: a person who moves in faster than the arm can escape must not
  /// make the QP infeasible (and stop the arm); the rows are then relaxed by
  /// the least common amount and the arm escapes as fast as its limits allow.
  bool soft() const override { return true; }

  /// The person for the next compute(). Real-time safe (plain copy).
  void setEnvironment(const CollisionEnvironment& env) { env_ = env; }

  /// Updates all distances (updateCollisions) and writes one row per pair
  /// closer than its iDist. Real-time safe.
  int compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C, Eigen::Ref<Eigen::VectorXd> lb,
              Eigen::Ref<Eigen::VectorXd> ub, Eigen::Ref<Eigen::VectorXd> chi_lb,
              Eigen::Ref<Eigen::VectorXd> chi_ub) override;

  /// Run-time switch of a pair rule by name (throws InputError if unknown;
  /// not real-time safe) or by index (real-time safe). Resets the dampers.
  void setRuleEnabled(const std::string& rule, bool enabled);
  void setRuleEnabled(int rule, bool enabled);
  bool ruleEnabled(int rule) const { return cdata_.rule_enabled[rule]; }

  const CollisionModel& collisionModel() const { return cmodel_; }
  const CollisionData& collisionData() const { return cdata_; }
  const std::vector<DamperState>& damperStates() const { return dampers_; }

 private:
  std::string name_;
  CollisionModel cmodel_;
  CollisionData cdata_;
  CollisionEnvironment env_;
  std::vector<DamperState> dampers_;
  double max_escape_ = 8.0;     ///< m/s^2, cap on a row's demanded d_ddot
  double reach_fraction_ = 0.5; ///< cap as a fraction of the row's reach
  double broadphase_ = 0.05;    ///< m, farthest a fast pair may engage beyond its iDist
};

/// The bound of one damper row in chi space, for a pair with distance d,
/// rate d_dot and drift: lb on Jd qddot. Exposed for tests. Real-time safe.
double damperLowerBound(double d, double d_dot, double drift, double xi, const DamperSettings& s, double dt);

}  // namespace handover::control
