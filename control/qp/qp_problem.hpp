// Dense convex QP in the form the controller builds every cycle:
//
//   minimise    1/2 x' H x + g' x
//   subject to  A_eq x = b_eq                   (n_eq rows used)
//               c_lb <= C x <= c_ub             (n_in rows used; +-inf = no bound)
//               x_lb <= x <= x_ub               (+-inf = no bound)
//
// Storage is reserved once at a capacity (reserve); the number of rows in use
// may change between cycles without allocating: only the top n_eq / n_in rows
// of A_eq / C are read. Not thread safe; one problem per controller.
//
// A lower side <= -kQpInfinity or an upper side >= kQpInfinity is absent. A
// row with c_lb == c_ub (or x_lb == x_ub) is an equality. NaN is never
// allowed. Units are the caller's; the solver's tolerances are relative.
#pragma once

#include <Eigen/Core>

namespace handover::control {

/// Sides at or beyond this magnitude (lower <= -it, upper >= it) are absent.
constexpr double kQpInfinity = 1e20;
/// Whether a row's (or variable's) lower / upper side is present.
inline bool hasLowerSide(double lb) { return lb > -kQpInfinity; }
inline bool hasUpperSide(double ub) { return ub < kQpInfinity; }

struct QpProblem {
  int n = 0;       ///< variables
  int n_eq = 0;    ///< equality rows in use
  int n_in = 0;    ///< two-sided inequality rows in use

  Eigen::MatrixXd H;     ///< n x n, symmetric positive definite
  Eigen::VectorXd g;     ///< n
  Eigen::MatrixXd A_eq;  ///< capacity_eq x n
  Eigen::VectorXd b_eq;  ///< capacity_eq
  Eigen::MatrixXd C;     ///< capacity_in x n
  Eigen::VectorXd c_lb;  ///< capacity_in
  Eigen::VectorXd c_ub;  ///< capacity_in
  Eigen::VectorXd x_lb;  ///< n
  Eigen::VectorXd x_ub;  ///< n
  /// capacity_in; 1 marks an inequality row that may be relaxed when the
  /// rows cannot all hold (SoftRowRelaxation), 0 a hard row. Solvers ignore it.
  Eigen::VectorXi soft_in;

  /// Sizes all storage (allocates; call at start-up), zeroes it, and sets
  /// n_eq = n_in = 0, unbounded rows and unbounded variables.
  /// Throws InputError for num_vars < 1 or negative capacities.
  void reserve(int num_vars, int capacity_eq, int capacity_in);
  int capacityEq() const { return static_cast<int>(A_eq.rows()); }
  /// Whether any of the n_in rows in use is soft.
  bool hasSoftRows() const { return n_in > 0 && (soft_in.head(n_in).array() != 0).any(); }
  int capacityIn() const { return static_cast<int>(C.rows()); }
};

enum class QpStatus {
  kOptimal,         ///< solution satisfies the KKT conditions
  kInfeasible,      ///< constraints cannot all hold
  kMaxIterations,   ///< iteration limit reached; x is not a solution
  kInvalidProblem,  ///< NaN/inf in data, H not positive definite, or sizes wrong
};

/// Lower-case name ("optimal", "infeasible", ...) for logs and result files.
const char* toString(QpStatus status);

}  // namespace handover::control
