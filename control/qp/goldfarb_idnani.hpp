// Goldfarb-Idnani dual active-set solver for small dense strictly convex QPs
// (QpProblem). Method: D. Goldfarb, A. Idnani, "A numerically stable dual
// method for solving strictly convex quadratic programs", Math. Prog. 27, 1983.
//
// It starts at the unconstrained minimum -H^-1 g, imposes the equalities, then
// repeatedly adds the most violated inequality side, taking dual (partial)
// steps that drop active sides whose multipliers would turn negative, until no
// side is violated. Every iterate is dual feasible, so an infeasible problem is
// detected as a violated side that no step can reach. It keeps H = L L' and
// J = L^-T Q, R (the QR factors of L^-1 N for the active normals N) up to date
// with Givens rotations, never refactorising, and finishes with one step of
// iterative refinement on the final active set. The point it returns is
// checked against every side: one that no longer holds (a step along a nearly
// dependent normal, taken in rounding) makes the solve kInfeasible, never a
// wrong kOptimal.
//
// Each finite side of a two-sided row is one constraint (+-inf sides cost one
// comparison); variable bounds are unit rows whose products are single
// entries; c_lb == c_ub and x_lb == x_ub are handled as equalities.
// Warm start re-imposes the previous optimal active set (as equalities) and
// keeps it only if the resulting multipliers are dual feasible; otherwise the
// offending sides are left out, and after a second failure the solve starts
// cold. The optimum of a strictly convex QP is unique, so both paths agree.
//
// Real-time safety: solve() allocates nothing once reserve() was called with
// sizes that fit the problem (and x has size n); its work is bounded by
// options().max_iterations.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "control/qp/qp_solver.hpp"

namespace handover::control {

class GoldfarbIdnaniSolver final : public QpSolver {
 public:
  explicit GoldfarbIdnaniSolver(const QpSolverOptions& options = QpSolverOptions{});

  void reserve(int num_vars, int capacity_eq, int capacity_in) override;
  QpStatus solve(const QpProblem& problem, Eigen::VectorXd& x) override;
  const QpResult& result() const override { return result_; }
  void setOptions(const QpSolverOptions& options) override;
  const QpSolverOptions& options() const override { return options_; }
  void resetWarmStart() override { warm_.clear(); }

 private:
  // How a side is added outside the dual loop (equalities, warm start).
  enum class AddOutcome { kAdded, kRedundant, kInconsistent };
  // Per-row classification, recomputed each solve.
  enum RowType : unsigned char { kFree = 0, kHasLower = 1, kHasUpper = 2, kFixed = 4 };

  QpStatus finish(QpStatus status, const char* message, Eigen::VectorXd& x);
  const char* checkProblem();
  bool factorize();
  void coldStart();
  void loadNormal(QpRowKind kind, int index);   // np_ = normal of the side (n'x >= b)
  double rhs(QpRowKind kind, int index) const;  // b of the side
  double slack(QpRowKind kind, int index) const;  // n'x - b at x_
  double normalNorm(QpRowKind kind, int index) const;
  void computeDirections(QpRowKind kind, int index);  // d_, z_, r_ for the current active set
  double tail2() const;                         // |d_2|^2 (part of d_ outside the active span)
  bool dependent(double d2sq, double np_norm) const;
  void appendActive(QpRowKind kind, int index, double multiplier, bool is_equality);
  void dropActive(int slot);
  AddOutcome addAsEquality(QpRowKind kind, int index);
  bool tryWarmStart();
  bool findMostViolated(QpRowKind& kind, int& index);
  QpStatus dualLoop(const char*& message);
  void refine();  // one step of iterative refinement on the final active set
  bool primalFeasible() const;  // x_ holds every side (after refine)
  void setActiveFlag(QpRowKind kind, int index, bool on);

  QpSolverOptions options_;
  QpResult result_;

  // capacities
  int cap_n_ = 0, cap_eq_ = 0, cap_in_ = 0;
  // problem being solved (valid during solve())
  const QpProblem* p_ = nullptr;
  int n_ = 0;

  // factors and iterate
  Eigen::MatrixXd L_;     // cap_n x cap_n, Cholesky factor of H (lower)
  Eigen::MatrixXd J0_;    // L^-T (upper triangular)
  Eigen::MatrixXd J_;     // L^-T Q
  Eigen::MatrixXd R_;     // upper-left q x q upper triangular
  Eigen::MatrixXd J_snap_, R_snap_;  // state after the equalities (warm-start retries)
  Eigen::VectorXd x_, x0_, x_snap_, u_snap_;
  Eigen::VectorXd d_, z_, r_, np_, u_, tmp_;
  double j_norm_ = 1.0;   // Frobenius norm of L^-1, scale for the dependency test

  // active set: slots 0..q_-1
  int q_ = 0;
  int q_snap_ = 0;
  std::vector<QpActiveRow> act_, act_snap_;
  std::vector<char> act_eq_, act_eq_snap_;

  // per-row data of this solve
  Eigen::VectorXd cx_;         // C x
  Eigen::VectorXd row_norm_;   // |C_i|
  Eigen::VectorXd eq_norm_;    // |A_eq_i|
  std::vector<unsigned char> row_type_, bnd_type_;
  std::vector<char> row_active_lo_, row_active_up_, bnd_active_lo_, bnd_active_up_;

  // warm start: inequality sides active at the last optimum
  std::vector<QpActiveRow> warm_;
};

}  // namespace handover::control
