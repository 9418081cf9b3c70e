// What a QP solve reports: status, work done, objective, multipliers and the
// active set. Sized once by the solver's reserve(); reading it never allocates.
//
// Multiplier convention (the same for every solver behind QpSolver): at an
// optimum x,
//   H x + g + A_eq' y_eq + C' y_in + y_x = 0,
// with y_in[i] <= 0 when row i rests on its lower side c_lb, >= 0 on its upper
// side c_ub, any sign when c_lb == c_ub, and 0 when the row is inactive; y_x
// likewise for the variable bounds; y_eq has any sign.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "control/qp/qp_problem.hpp"

namespace handover::control {

/// Which constraint a row of the active set is.
enum class QpRowKind : std::uint8_t {
  kEquality,    ///< row `index` of A_eq
  kRowLower,    ///< row `index` of C held at c_lb
  kRowUpper,    ///< row `index` of C held at c_ub
  kRowFixed,    ///< row `index` of C with c_lb == c_ub (an equality)
  kBoundLower,  ///< variable `index` held at x_lb
  kBoundUpper,  ///< variable `index` held at x_ub
  kBoundFixed,  ///< variable `index` with x_lb == x_ub (an equality)
};

const char* toString(QpRowKind kind);

struct QpActiveRow {
  QpRowKind kind = QpRowKind::kEquality;
  int index = 0;  ///< row of A_eq / C, or variable index, per kind
  bool operator==(const QpActiveRow& o) const { return kind == o.kind && index == o.index; }
};

struct QpResult {
  QpStatus status = QpStatus::kInvalidProblem;
  /// Why the status is not kOptimal (static text; "" when optimal).
  const char* message = "";
  /// Dual active-set changes (constraint additions and drops) of this solve.
  /// Equalities and warm-start rows, which are re-imposed directly, are not counted.
  int iterations = 0;
  bool warm_started = false;   ///< the previous active set seeded this solve
  double objective = 0.0;      ///< 1/2 x'Hx + g'x at the returned x
  Eigen::VectorXd y_eq;        ///< capacity_eq; first n_eq entries valid
  Eigen::VectorXd y_in;        ///< capacity_in; first n_in entries valid
  Eigen::VectorXd y_x;         ///< n
  /// Linearly independent active constraints at the returned x (at most n).
  /// Redundant equalities are left out (their multiplier is 0).
  std::vector<QpActiveRow> active;
};

}  // namespace handover::control
