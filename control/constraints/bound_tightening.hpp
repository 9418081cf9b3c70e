// Tightening of the variable bounds chi_lb <= chi <= chi_ub that never makes
// them cross: a new bound is clamped into the interval left by the
// constraints registered before (e.g. the acceleration limits), so that
// limits of lower rank give way instead of making the QP infeasible.
// Header-only, real-time safe.
#pragma once

#include <algorithm>

#include <Eigen/Core>

namespace handover::control {

inline void tightenBounds(Eigen::Ref<Eigen::VectorXd> chi_lb, Eigen::Ref<Eigen::VectorXd> chi_ub, int i, double lb,
                          double ub) {
  if (lb > chi_lb[i]) chi_lb[i] = std::min(lb, chi_ub[i]);
  if (ub < chi_ub[i]) chi_ub[i] = std::max(ub, chi_lb[i]);
}

}  // namespace handover::control
