// Test helpers for the QP solver: random feasible strictly convex problems
// and an independent KKT checker (scale-aware residuals).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "control/qp/qp_problem.hpp"
#include "control/qp/qp_result.hpp"

namespace handover::control::test {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct RandomQpSpec {
  int n = 5;
  int n_eq = 0;
  int n_in = 10;
  bool bounds = true;
  /// Chance that a row side (or bound side) is infinite.
  double p_inf = 0.25;
  /// Size of the linear term: large values push the unconstrained minimum far
  /// outside the feasible set, so many constraints become active.
  double g_scale = 10.0;
};

/// Random problem that is feasible by construction (a random point satisfies
/// every constraint) and has a positive definite H with moderate conditioning.
inline void makeRandomQp(const RandomQpSpec& s, std::mt19937& rng, QpProblem& p) {
  std::normal_distribution<double> nd(0.0, 1.0);
  std::uniform_real_distribution<double> ud(0.0, 1.0);
  p.reserve(s.n, std::max(s.n_eq, 1), std::max(s.n_in, 1));
  p.n_eq = s.n_eq;
  p.n_in = s.n_in;
  Eigen::MatrixXd M(s.n, s.n);
  for (int i = 0; i < s.n; ++i)
    for (int j = 0; j < s.n; ++j) M(i, j) = nd(rng);
  p.H = M.transpose() * M + 0.1 * Eigen::MatrixXd::Identity(s.n, s.n);
  for (int j = 0; j < s.n; ++j) p.g[j] = s.g_scale * nd(rng);
  Eigen::VectorXd xf(s.n);
  for (int j = 0; j < s.n; ++j) xf[j] = nd(rng);
  for (int i = 0; i < s.n_eq; ++i) {
    for (int j = 0; j < s.n; ++j) p.A_eq(i, j) = nd(rng);
    p.b_eq[i] = p.A_eq.row(i).dot(xf);
  }
  for (int i = 0; i < s.n_in; ++i) {
    for (int j = 0; j < s.n; ++j) p.C(i, j) = nd(rng);
    const double v = p.C.row(i).dot(xf);
    p.c_lb[i] = ud(rng) < s.p_inf ? -kInfinity : v - ud(rng);
    p.c_ub[i] = ud(rng) < s.p_inf ? kInfinity : v + ud(rng);
  }
  if (s.bounds) {
    for (int j = 0; j < s.n; ++j) {
      p.x_lb[j] = ud(rng) < s.p_inf ? -kInfinity : xf[j] - ud(rng);
      p.x_ub[j] = ud(rng) < s.p_inf ? kInfinity : xf[j] + ud(rng);
    }
  }
}

/// Scale-aware KKT residuals of (x, multipliers) for problem p, using the
/// documented convention H x + g + A_eq'y_eq + C'y_in + y_x = 0 with y <= 0 on
/// lower sides and y >= 0 on upper sides. Every entry is a relative measure.
struct KktResiduals {
  double stationarity = 0.0;
  double primal = 0.0;
  double dual = 0.0;
  double complementarity = 0.0;
  double worst() const { return std::max({stationarity, primal, dual, complementarity}); }
};

inline KktResiduals kktResiduals(const QpProblem& p, const Eigen::VectorXd& x, const QpResult& r) {
  KktResiduals k;
  const int n = p.n;
  const auto A = p.A_eq.topRows(p.n_eq);
  const auto C = p.C.topRows(p.n_in);
  const Eigen::VectorXd y_eq = r.y_eq.head(p.n_eq);
  const Eigen::VectorXd y_in = r.y_in.head(p.n_in);
  const Eigen::VectorXd y_x = r.y_x.head(n);
  const Eigen::VectorXd Hx = p.H * x;
  const Eigen::VectorXd Ay = A.transpose() * y_eq;
  const Eigen::VectorXd Cy = C.transpose() * y_in;
  const Eigen::VectorXd res = Hx + p.g + Ay + Cy + y_x;
  auto inf = [](const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; };
  const double s_scale =
      1.0 + std::max({inf(Hx), inf(p.g), inf(Ay), inf(Cy), inf(y_x)});
  k.stationarity = inf(res) / s_scale;

  const double xn = inf(x);
  auto side = [&](double value, double lb, double ub, double row_norm, double y) {
    const bool has_lb = lb > -kQpInfinity;
    const bool has_ub = ub < kQpInfinity;
    const double scale_lb = 1.0 + std::abs(has_lb ? lb : 0.0) + row_norm * xn;
    const double scale_ub = 1.0 + std::abs(has_ub ? ub : 0.0) + row_norm * xn;
    if (has_lb) k.primal = std::max(k.primal, (lb - value) / scale_lb);
    if (has_ub) k.primal = std::max(k.primal, (value - ub) / scale_ub);
    const double y_scale = 1.0 + std::abs(y);
    if (y < 0.0) {  // claims the lower side is active
      if (!has_lb) k.dual = std::max(k.dual, -y / y_scale);
      else k.complementarity = std::max(k.complementarity,
                                        std::abs(y) * std::abs(value - lb) / (y_scale * scale_lb));
    }
    if (y > 0.0) {
      if (!has_ub) k.dual = std::max(k.dual, y / y_scale);
      else k.complementarity = std::max(k.complementarity,
                                        std::abs(y) * std::abs(ub - value) / (y_scale * scale_ub));
    }
  };
  for (int i = 0; i < p.n_eq; ++i) {
    const double v = A.row(i).dot(x);
    k.primal = std::max(k.primal, std::abs(v - p.b_eq[i]) /
                                      (1.0 + std::abs(p.b_eq[i]) + A.row(i).norm() * xn));
  }
  for (int i = 0; i < p.n_in; ++i)
    side(C.row(i).dot(x), p.c_lb[i], p.c_ub[i], C.row(i).norm(), y_in[i]);
  for (int j = 0; j < n; ++j) side(x[j], p.x_lb[j], p.x_ub[j], 1.0, y_x[j]);
  return k;
}

/// Reads a problem saved as text (tests/control/qp/data/*.txt): a first line
/// of comment, then n n_eq n_in; H row by row; g; each inequality row as
/// C(i, :) c_lb c_ub soft; each variable as x_lb x_ub (no equality rows).
/// Returns false when the file is missing or short.
inline bool loadQpText(const std::string& path, QpProblem& p) {
  std::ifstream in(path);
  std::string comment;
  if (!std::getline(in, comment)) return false;
  int n = 0, n_eq = 0, n_in = 0;
  if (!(in >> n >> n_eq >> n_in) || n < 1 || n_eq != 0 || n_in < 0) return false;
  p.reserve(n, 0, n_in);
  p.n_in = n_in;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) in >> p.H(i, j);
  for (int i = 0; i < n; ++i) in >> p.g[i];
  for (int r = 0; r < n_in; ++r) {
    for (int j = 0; j < n; ++j) in >> p.C(r, j);
    in >> p.c_lb[r] >> p.c_ub[r] >> p.soft_in[r];
  }
  for (int i = 0; i < n; ++i) in >> p.x_lb[i] >> p.x_ub[i];
  return static_cast<bool>(in);
}

/// The controller step whose two collision rows have nearly opposite normals
/// (tests/control/qp/data: a give's gripper straddling a capsule; infeasible).
inline std::string nearlyInconsistentRowsFile() {
  return std::string(HANDOVER_SOURCE_DIR) + "/tests/control/qp/data/nearly_inconsistent_collision_rows.txt";
}

/// Largest amount by which x violates a row side or a bound of p (0 when
/// every side holds), each row widened by `widen` where it is soft.
inline double largestViolation(const QpProblem& p, const Eigen::VectorXd& x, double widen = 0.0) {
  double v = 0.0;
  for (int i = 0; i < p.n_in; ++i) {
    const double w = p.soft_in[i] != 0 ? widen : 0.0;
    const double cx = p.C.row(i).dot(x);
    v = std::max({v, p.c_lb[i] - w - cx, cx - p.c_ub[i] - w});
  }
  for (int j = 0; j < p.n; ++j) v = std::max({v, p.x_lb[j] - x[j], x[j] - p.x_ub[j]});
  return v;
}

}  // namespace handover::control::test
