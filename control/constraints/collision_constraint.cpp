#include <algorithm>
#include "control/constraints/collision_constraint.hpp"

#include <limits>

namespace handover::control {

double damperLowerBound(double d, double d_dot, double drift, double xi, const DamperSettings& s, double dt) {
  const double bound = -xi * (d - s.s_dist) / (s.i_dist - s.s_dist);
  return (bound - d_dot) / dt - drift;
}

CollisionConstraint::CollisionConstraint(const Model& model, const CollisionConfig& config, std::string name)
    : name_(std::move(name)),
      cmodel_(buildCollisionModel(model, config)),
      cdata_(cmodel_),
      dampers_(cmodel_.pairs.size()),
      max_escape_(config.max_escape_acceleration),
      reach_fraction_(config.escape_reach_fraction),
      broadphase_(config.broadphase_margin) {}

void CollisionConstraint::setRuleEnabled(int rule, bool enabled) {
  control::setRuleEnabled(cdata_, rule, enabled);
  for (int k = 0; k < cmodel_.numPairs(); ++k)
    if (cmodel_.pairs[k].rule == rule) dampers_[k] = DamperState{};
}

void CollisionConstraint::setRuleEnabled(const std::string& rule, bool enabled) {
  control::setRuleEnabled(cmodel_, cdata_, rule, enabled);  // throws on unknown names
  setRuleEnabled(cmodel_.ruleIndex(rule), enabled);
}

int CollisionConstraint::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> C,
                                 Eigen::Ref<Eigen::VectorXd> lb, Eigen::Ref<Eigen::VectorXd> ub,
                                 Eigen::Ref<Eigen::VectorXd> /*chi_lb*/, Eigen::Ref<Eigen::VectorXd> /*chi_ub*/) {
  updateCollisions(cmodel_, cdata_, *ctx.model, *ctx.data, env_);
  const double inf = std::numeric_limits<double>::infinity();
  int rows = 0;
  for (int k = 0; k < cmodel_.numPairs(); ++k) {
    const PairResult& r = cdata_.results[k];
    const DamperSettings& s = cmodel_.pairs[k].damper;
    DamperState& st = dampers_[k];
    if (!r.active) {
      st = DamperState{};
      continue;
    }
    // What this row may demand (keeps the QP feasible when the person moves in
    // fast): at most max_escape, and at most half of what this row alone could
    // reach with every joint at its acceleration limit (a row through a
    // near-singular direction or a point near the base cannot do much).
    const double reach = r.jacobian.cwiseAbs().dot(ctx.model->a_max.transpose());
    const double escape = std::min(max_escape_, reach_fraction_ * reach);
    if (!st.inside) {
      // a pair closing fast engages early enough for the arm to give way at
      // what the row may demand (a damper entered at d slows the approach
      // linearly to 0 at sDist: it demands v^2 / (d - sDist) at entry), as far
      // out as the broad phase computes pairs
      const double closing = std::max(0.0, -r.d_dot);
      const double engage =
          escape > 0.0 ? std::clamp(s.s_dist + closing * closing / escape, s.i_dist, s.i_dist + broadphase_)
                       : s.i_dist;
      if (r.distance >= engage) continue;
      // entering: automatic damping accepts the current approach speed
      st.inside = true;
      st.i_dist = engage;
      if (s.automatic) {
        st.xi = s.damping_offset;
        if (r.d_dot < 0.0 && r.distance > s.s_dist)
          st.xi += -r.d_dot * (engage - s.s_dist) / (r.distance - s.s_dist);
      }
    } else if (r.distance >= st.i_dist) {
      st = DamperState{};
      continue;
    }
    if (!s.automatic) st.xi = s.damping;
    st.bound = -st.xi * (r.distance - s.s_dist) / (st.i_dist - s.s_dist);

    C.row(rows).setZero();
    C.row(rows).segment<kArmDofs>(VariableLayout::kQdd) = r.jacobian;
    // d_ddot = Jd qddot + drift >= demand, the demand capped at `escape`
    DamperSettings engaged = s;
    engaged.i_dist = st.i_dist;
    const double demand = damperLowerBound(r.distance, r.d_dot, r.drift, st.xi, engaged, ctx.dt) + r.drift;
    lb[rows] = std::min(demand, escape) - r.drift;
    ub[rows] = inf;
    ++rows;
  }
  return rows;
}

}  // namespace handover::control
