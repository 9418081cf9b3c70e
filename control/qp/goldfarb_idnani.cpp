#include "control/qp/goldfarb_idnani.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "config/input_error.hpp"

namespace handover::control {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A normal whose part outside the active span, |d2|, is below this fraction
// of |L^-1| |n| is treated as linearly dependent on the active normals
// (rounding in d = J'n is about n * eps of that scale).
constexpr double kDependency = 1e-12;
// H is rejected when a Cholesky pivot^2 falls below this fraction of max H_ii
// (condition numbers up to ~1e13 pass).
constexpr double kPivot = 1e-13;
// H must be symmetric to this fraction of its largest entry.
constexpr double kSymmetry = 1e-10;
// Entries of r at or below this fraction of |r|_inf are rounding noise.
constexpr double kRPositive = 1e-12;
// Warm-start multipliers below -kDual * (1 + max|u|) are genuinely negative.
constexpr double kDual = 1e-10;
// The returned point must satisfy every side to this fraction of the side's
// own scale, |n| + sum_j |n_j x_j| + |b| (the solver's tolerance convention
// plus the rounding of n'x): a solve that stepped along a nearly dependent
// normal reaches points 1e14 away whose rows no longer hold, and must not be
// called optimal.
constexpr double kVerify = 1e-7;

bool isEqualityKind(QpRowKind k) {
  return k == QpRowKind::kEquality || k == QpRowKind::kRowFixed || k == QpRowKind::kBoundFixed;
}
bool isBoundKind(QpRowKind k) {
  return k == QpRowKind::kBoundLower || k == QpRowKind::kBoundUpper || k == QpRowKind::kBoundFixed;
}

// Givens rotation applied to columns a and b of M (first `rows` rows):
// [a b] <- [c a + s b, -s a + c b].
inline void rotateColumns(Eigen::MatrixXd& M, int rows, int a, int b, double c, double s) {
  double* __restrict pa = M.col(a).data();
  double* __restrict pb = M.col(b).data();
  for (int k = 0; k < rows; ++k) {
    const double t1 = pa[k];
    const double t2 = pb[k];
    pa[k] = c * t1 + s * t2;
    pb[k] = -s * t1 + c * t2;
  }
}

// True when the rows x cols block at `m` (column-major, leading dimension
// `ld`) holds only finite numbers: v * 0 is NaN exactly for NaN and +-inf, and
// the sum has no early exit so the loop vectorises.
bool allFinite(const double* m, int rows, int cols, Eigen::Index ld) {
  double acc = 0.0;
  for (int j = 0; j < cols; ++j) {
    const double* c = m + j * ld;
    for (int i = 0; i < rows; ++i) acc += c[i] * 0.0;
  }
  return acc == 0.0;
}
bool hasNaN(const double* v, int size) {
  bool nan = false;
  for (int i = 0; i < size; ++i) nan |= std::isnan(v[i]);
  return nan;
}

}  // namespace

GoldfarbIdnaniSolver::GoldfarbIdnaniSolver(const QpSolverOptions& options) { setOptions(options); }

void GoldfarbIdnaniSolver::setOptions(const QpSolverOptions& options) {
  validate(options);
  options_ = options;
}

void GoldfarbIdnaniSolver::reserve(int num_vars, int capacity_eq, int capacity_in) {
  if (num_vars < 1 || capacity_eq < 0 || capacity_in < 0) {
    throw InputError("GoldfarbIdnaniSolver::reserve: invalid sizes (num_vars=" +
                     std::to_string(num_vars) + ", capacity_eq=" + std::to_string(capacity_eq) +
                     ", capacity_in=" + std::to_string(capacity_in) + ")");
  }
  cap_n_ = num_vars;
  cap_eq_ = capacity_eq;
  cap_in_ = capacity_in;
  const int n = num_vars;
  for (Eigen::MatrixXd* m : {&L_, &J0_, &J_, &R_, &J_snap_}) m->setZero(n, n);
  for (Eigen::VectorXd* v : {&x_, &x0_, &x_snap_, &u_snap_, &d_, &z_, &r_, &np_, &u_, &tmp_})
    v->setZero(n);
  act_.assign(n, QpActiveRow{});
  act_eq_.assign(n, 0);
  cx_.setZero(capacity_in);
  row_norm_.setZero(capacity_in);
  eq_norm_.setZero(capacity_eq);
  row_type_.assign(capacity_in, kFree);
  bnd_type_.assign(n, kFree);
  row_active_lo_.assign(capacity_in, 0);
  row_active_up_.assign(capacity_in, 0);
  bnd_active_lo_.assign(n, 0);
  bnd_active_up_.assign(n, 0);
  result_.y_eq.setZero(capacity_eq);
  result_.y_in.setZero(capacity_in);
  result_.y_x.setZero(n);
  result_.active.clear();
  result_.active.reserve(n);
  warm_.clear();
  warm_.reserve(n);
}

// ---------------------------------------------------------------- checks

const char* GoldfarbIdnaniSolver::checkProblem() {
  const QpProblem& p = *p_;
  if (cap_n_ == 0) return "solver not reserved (call reserve() first)";
  if (p.n < 1 || p.n > cap_n_) return "number of variables does not fit the reserved size";
  if (p.n_eq < 0 || p.n_eq > cap_eq_) return "n_eq does not fit the reserved equality capacity";
  if (p.n_in < 0 || p.n_in > cap_in_) return "n_in does not fit the reserved inequality capacity";
  const int n = p.n;
  if (p.H.rows() != n || p.H.cols() != n || p.g.size() != n || p.x_lb.size() != n ||
      p.x_ub.size() != n)
    return "H, g, x_lb or x_ub does not have n rows";
  if (p.n_eq > 0 && (p.A_eq.cols() != n || p.A_eq.rows() < p.n_eq || p.b_eq.size() < p.n_eq))
    return "A_eq or b_eq is smaller than n_eq x n";
  if (p.n_in > 0 && (p.C.cols() != n || p.C.rows() < p.n_in || p.c_lb.size() < p.n_in ||
                     p.c_ub.size() < p.n_in))
    return "C, c_lb or c_ub is smaller than n_in x n";
  if (!allFinite(p.H.data(), n, n, p.H.outerStride()) || !allFinite(p.g.data(), n, 1, n))
    return "H or g contains NaN or inf";
  if (p.n_eq > 0 && (!allFinite(p.A_eq.data(), p.n_eq, n, p.A_eq.outerStride()) ||
                     !allFinite(p.b_eq.data(), p.n_eq, 1, p.n_eq)))
    return "A_eq or b_eq contains NaN or inf";
  if (p.n_in > 0 && (!allFinite(p.C.data(), p.n_in, n, p.C.outerStride()) ||
                     hasNaN(p.c_lb.data(), p.n_in) || hasNaN(p.c_ub.data(), p.n_in)))
    return "C contains NaN or inf, or c_lb / c_ub contains NaN";
  if (hasNaN(p.x_lb.data(), n) || hasNaN(p.x_ub.data(), n)) return "x_lb or x_ub contains NaN";
  const double hmax = p.H.cwiseAbs().maxCoeff();
  for (int j = 0; j < n; ++j)
    for (int i = j + 1; i < n; ++i)
      if (std::abs(p.H(i, j) - p.H(j, i)) > kSymmetry * hmax) return "H is not symmetric";
  return nullptr;
}

bool GoldfarbIdnaniSolver::factorize() {
  const int n = n_;
  const Eigen::MatrixXd& H = p_->H;
  const double dmax = H.diagonal().maxCoeff();
  if (!(dmax > 0.0)) return false;
  // H = L L' (lower), right-looking so every inner loop runs down a column
  for (int j = 0; j < n; ++j) {
    const double* h = H.col(j).data();
    double* l = L_.col(j).data();
    for (int i = j; i < n; ++i) l[i] = h[i];
  }
  for (int j = 0; j < n; ++j) {
    double* __restrict lj = L_.col(j).data();
    const double diag = lj[j];
    if (!(diag > kPivot * dmax)) return false;
    const double ljj = std::sqrt(diag);
    const double inv = 1.0 / ljj;
    lj[j] = ljj;
    for (int i = j + 1; i < n; ++i) lj[i] *= inv;
    for (int k = j + 1; k < n; ++k) {
      double* __restrict lk = L_.col(k).data();
      const double f = lj[k];
      for (int i = k; i < n; ++i) lk[i] -= f * lj[i];
    }
  }
  // J0 = L^-T, upper triangular: solve L' J0 = I column by column
  double frob = 0.0;
  for (int j = 0; j < n; ++j) {
    double* __restrict jc = J0_.col(j).data();
    for (int i = j + 1; i < n; ++i) jc[i] = 0.0;
    jc[j] = 1.0 / L_(j, j);
    for (int i = j - 1; i >= 0; --i) {
      const double* __restrict li = L_.col(i).data();
      double v = 0.0;
      for (int k = i + 1; k <= j; ++k) v -= li[k] * jc[k];
      jc[i] = v / li[i];
    }
    for (int i = 0; i <= j; ++i) frob += jc[i] * jc[i];
  }
  j_norm_ = std::sqrt(frob);
  // unconstrained minimum x0 = -H^-1 g = -J0 J0' g
  auto J0 = J0_.topLeftCorner(n, n);
  tmp_.head(n).noalias() = J0.transpose() * p_->g;
  x0_.head(n).noalias() = J0 * tmp_.head(n);  // (a negated product would need a temporary)
  x0_.head(n) = -x0_.head(n);
  return true;
}

// ---------------------------------------------------------------- sides

double GoldfarbIdnaniSolver::rhs(QpRowKind kind, int i) const {
  const QpProblem& p = *p_;
  switch (kind) {
    case QpRowKind::kEquality: return p.b_eq[i];
    case QpRowKind::kRowLower: return p.c_lb[i];
    case QpRowKind::kRowUpper: return -p.c_ub[i];
    case QpRowKind::kRowFixed: return 0.5 * (p.c_lb[i] + p.c_ub[i]);
    case QpRowKind::kBoundLower: return p.x_lb[i];
    case QpRowKind::kBoundUpper: return -p.x_ub[i];
    case QpRowKind::kBoundFixed: return 0.5 * (p.x_lb[i] + p.x_ub[i]);
  }
  return 0.0;
}

double GoldfarbIdnaniSolver::slack(QpRowKind kind, int i) const {
  const QpProblem& p = *p_;
  const auto x = x_.head(n_);
  switch (kind) {
    case QpRowKind::kEquality: return p.A_eq.row(i).dot(x) - p.b_eq[i];
    case QpRowKind::kRowLower: return p.C.row(i).dot(x) - p.c_lb[i];
    case QpRowKind::kRowUpper: return p.c_ub[i] - p.C.row(i).dot(x);
    case QpRowKind::kRowFixed: return p.C.row(i).dot(x) - rhs(kind, i);
    case QpRowKind::kBoundLower: return x[i] - p.x_lb[i];
    case QpRowKind::kBoundUpper: return p.x_ub[i] - x[i];
    case QpRowKind::kBoundFixed: return x[i] - rhs(kind, i);
  }
  return 0.0;
}

double GoldfarbIdnaniSolver::normalNorm(QpRowKind kind, int i) const {
  if (kind == QpRowKind::kEquality) return eq_norm_[i];
  if (isBoundKind(kind)) return 1.0;
  return row_norm_[i];
}

void GoldfarbIdnaniSolver::loadNormal(QpRowKind kind, int i) {
  const int n = n_;
  switch (kind) {
    case QpRowKind::kEquality:
      for (int j = 0; j < n; ++j) np_[j] = p_->A_eq(i, j);
      break;
    case QpRowKind::kRowLower:
    case QpRowKind::kRowFixed:
      for (int j = 0; j < n; ++j) np_[j] = p_->C(i, j);
      break;
    case QpRowKind::kRowUpper:
      for (int j = 0; j < n; ++j) np_[j] = -p_->C(i, j);
      break;
    default:  // bounds never go through np_
      break;
  }
}

void GoldfarbIdnaniSolver::setActiveFlag(QpRowKind kind, int i, bool on) {
  switch (kind) {
    case QpRowKind::kRowLower: row_active_lo_[i] = on; break;
    case QpRowKind::kRowUpper: row_active_up_[i] = on; break;
    case QpRowKind::kBoundLower: bnd_active_lo_[i] = on; break;
    case QpRowKind::kBoundUpper: bnd_active_up_[i] = on; break;
    default: break;  // equalities are never scanned for violation
  }
}

// ---------------------------------------------------------------- core algebra

// d = J' n, z = J2 d2 (primal step direction), r = R^-1 d1 (change of the
// active multipliers per unit multiplier of the new side). For a bound, J' n
// is one row of J.
void GoldfarbIdnaniSolver::computeDirections(QpRowKind kind, int index) {
  const int n = n_;
  const int q = q_;
  if (isBoundKind(kind)) {
    const double sgn = kind == QpRowKind::kBoundUpper ? -1.0 : 1.0;
    for (int j = 0; j < n; ++j) d_[j] = sgn * J_(index, j);
  } else {
    loadNormal(kind, index);
    d_.head(n).noalias() = J_.topLeftCorner(n, n).transpose() * np_.head(n);
  }
  if (q < n)
    z_.head(n).noalias() = J_.block(0, q, n, n - q) * d_.segment(q, n - q);
  else
    z_.head(n).setZero();
  for (int i = q - 1; i >= 0; --i) {
    double v = d_[i];
    for (int k = i + 1; k < q; ++k) v -= R_(i, k) * r_[k];
    r_[i] = v / R_(i, i);
  }
}

double GoldfarbIdnaniSolver::tail2() const {
  return q_ < n_ ? d_.segment(q_, n_ - q_).squaredNorm() : 0.0;
}

bool GoldfarbIdnaniSolver::dependent(double d2sq, double np_norm) const {
  const double thr = kDependency * j_norm_ * np_norm;
  return q_ >= n_ || d2sq <= thr * thr;
}

// Adds the side whose d_ was just computed: rotate d_'s tail into entry q so
// that J' n = [R(:,q); 0], then grow R by that column.
void GoldfarbIdnaniSolver::appendActive(QpRowKind kind, int index, double multiplier,
                                        bool is_equality) {
  const int n = n_;
  const int q = q_;
  for (int j = n - 1; j > q; --j) {
    const double a = d_[j - 1];
    const double b = d_[j];
    if (b == 0.0) continue;
    const double h = std::sqrt(a * a + b * b);
    const double c = a / h;
    const double s = b / h;
    d_[j - 1] = h;
    d_[j] = 0.0;
    rotateColumns(J_, n, j - 1, j, c, s);
  }
  for (int i = 0; i <= q; ++i) R_(i, q) = d_[i];
  act_[q] = QpActiveRow{kind, index};
  act_eq_[q] = is_equality;
  u_[q] = multiplier;
  setActiveFlag(kind, index, true);
  q_ = q + 1;
}

// Removes slot `slot`: delete its column of R, then restore the triangle with
// rotations of adjacent rows (applied to the matching columns of J).
void GoldfarbIdnaniSolver::dropActive(int slot) {
  const int n = n_;
  const int q = q_;
  setActiveFlag(act_[slot].kind, act_[slot].index, false);
  for (int col = slot; col < q - 1; ++col) {
    for (int i = 0; i <= col + 1; ++i) R_(i, col) = R_(i, col + 1);
    act_[col] = act_[col + 1];
    act_eq_[col] = act_eq_[col + 1];
    u_[col] = u_[col + 1];
  }
  for (int col = slot; col < q - 1; ++col) {
    const double a = R_(col, col);
    const double b = R_(col + 1, col);
    if (b == 0.0) continue;
    const double h = std::sqrt(a * a + b * b);
    const double c = a / h;
    const double s = b / h;
    R_(col, col) = h;
    R_(col + 1, col) = 0.0;
    for (int cc = col + 1; cc < q - 1; ++cc) {
      const double t1 = R_(col, cc);
      const double t2 = R_(col + 1, cc);
      R_(col, cc) = c * t1 + s * t2;
      R_(col + 1, cc) = -s * t1 + c * t2;
    }
    rotateColumns(J_, n, col, col + 1, c, s);
  }
  q_ = q - 1;
}

// Imposes a side as an equality with a full primal step (multiplier of any
// sign). Used for equalities and for re-imposing a warm-start active set.
GoldfarbIdnaniSolver::AddOutcome GoldfarbIdnaniSolver::addAsEquality(QpRowKind kind, int index) {
  computeDirections(kind, index);
  const double d2sq = tail2();
  const double s = slack(kind, index);
  const double nrm = normalNorm(kind, index);
  if (dependent(d2sq, nrm)) {
    const double b = rhs(kind, index);
    return std::abs(s) <= options_.tolerance * (nrm + std::abs(b)) ? AddOutcome::kRedundant
                                                                     : AddOutcome::kInconsistent;
  }
  const double t = -s / d2sq;
  const int n = n_;
  x_.head(n) += t * z_.head(n);
  u_.head(q_) -= t * r_.head(q_);
  appendActive(kind, index, t, isEqualityKind(kind));
  return AddOutcome::kAdded;
}

// ---------------------------------------------------------------- phases

void GoldfarbIdnaniSolver::coldStart() {
  const int n = n_;
  J_.topLeftCorner(n, n) = J0_.topLeftCorner(n, n);
  x_.head(n) = x0_.head(n);
  q_ = 0;
}

bool GoldfarbIdnaniSolver::tryWarmStart() {
  if (!options_.warm_start || warm_.empty()) return false;
  const int n = n_;
  const QpProblem& p = *p_;
  // snapshot of the state after the equalities; the R and slots below q_snap_
  // are not touched by later appends, so only J, x and u need copies
  q_snap_ = q_;
  J_snap_.topLeftCorner(n, n) = J_.topLeftCorner(n, n);
  x_snap_.head(n) = x_.head(n);
  u_snap_.head(q_) = u_.head(q_);

  for (int attempt = 0; attempt < 2; ++attempt) {
    bool any = false;
    for (QpActiveRow& w : warm_) {
      if (w.index < 0) continue;
      bool usable = false;
      switch (w.kind) {
        case QpRowKind::kRowLower:
          usable = w.index < p.n_in && (row_type_[w.index] & kHasLower) &&
                   !(row_type_[w.index] & kFixed) && !row_active_lo_[w.index];
          break;
        case QpRowKind::kRowUpper:
          usable = w.index < p.n_in && (row_type_[w.index] & kHasUpper) &&
                   !(row_type_[w.index] & kFixed) && !row_active_up_[w.index];
          break;
        case QpRowKind::kBoundLower:
          usable = w.index < n && (bnd_type_[w.index] & kHasLower) &&
                   !(bnd_type_[w.index] & kFixed) && !bnd_active_lo_[w.index];
          break;
        case QpRowKind::kBoundUpper:
          usable = w.index < n && (bnd_type_[w.index] & kHasUpper) &&
                   !(bnd_type_[w.index] & kFixed) && !bnd_active_up_[w.index];
          break;
        default: break;
      }
      // a side that no longer exists or is now dependent is simply left out
      if (!usable || addAsEquality(w.kind, w.index) != AddOutcome::kAdded) {
        w.index = -1;
        continue;
      }
      any = true;
    }
    if (!any) return false;
    // the start must be dual feasible: inequality multipliers >= 0
    double umax = 0.0;
    for (int k = 0; k < q_; ++k) umax = std::max(umax, std::abs(u_[k]));
    const double neg = -kDual * (1.0 + umax);
    bool feasible = true;
    for (int k = q_snap_; k < q_; ++k) {
      if (u_[k] < neg) {
        feasible = false;
        for (QpActiveRow& w : warm_)
          if (w == act_[k]) w.index = -1;
      }
    }
    if (feasible) {
      for (int k = q_snap_; k < q_; ++k) u_[k] = std::max(u_[k], 0.0);
      return true;
    }
    // back to the state after the equalities
    for (int k = q_snap_; k < q_; ++k) setActiveFlag(act_[k].kind, act_[k].index, false);
    q_ = q_snap_;
    J_.topLeftCorner(n, n) = J_snap_.topLeftCorner(n, n);
    x_.head(n) = x_snap_.head(n);
    u_.head(q_) = u_snap_.head(q_);
  }
  return false;
}

bool GoldfarbIdnaniSolver::findMostViolated(QpRowKind& kind, int& index) {
  const QpProblem& p = *p_;
  const int n = n_;
  const double tol = options_.tolerance;
  double best = 0.0;
  bool found = false;
  auto consider = [&](double s, double nrm, double b, QpRowKind k, int i) {
    if (s < -tol * (nrm + std::abs(b))) {
      const double measure = nrm > 0.0 ? -s / nrm : kInf;
      if (!found || measure > best) {
        best = measure;
        kind = k;
        index = i;
        found = true;
      }
    }
  };
  if (p.n_in > 0) {
    cx_.head(p.n_in).noalias() = p.C.topRows(p.n_in) * x_.head(n);
    for (int i = 0; i < p.n_in; ++i) {
      const unsigned char t = row_type_[i];
      if (t == kFree || (t & kFixed)) continue;
      const double v = cx_[i];
      const double nrm = row_norm_[i];
      if ((t & kHasLower) && !row_active_lo_[i])
        consider(v - p.c_lb[i], nrm, p.c_lb[i], QpRowKind::kRowLower, i);
      if ((t & kHasUpper) && !row_active_up_[i])
        consider(p.c_ub[i] - v, nrm, p.c_ub[i], QpRowKind::kRowUpper, i);
    }
  }
  for (int j = 0; j < n; ++j) {
    const unsigned char t = bnd_type_[j];
    if (t == kFree || (t & kFixed)) continue;
    if ((t & kHasLower) && !bnd_active_lo_[j])
      consider(x_[j] - p.x_lb[j], 1.0, p.x_lb[j], QpRowKind::kBoundLower, j);
    if ((t & kHasUpper) && !bnd_active_up_[j])
      consider(p.x_ub[j] - x_[j], 1.0, p.x_ub[j], QpRowKind::kBoundUpper, j);
  }
  return found;
}

// The dual loop: add the most violated side, taking partial (dual) steps
// that drop active sides whose multipliers reach zero first.
QpStatus GoldfarbIdnaniSolver::dualLoop(const char*& message) {
  const int n = n_;
  QpRowKind kind = QpRowKind::kRowLower;
  int index = 0;
  while (findMostViolated(kind, index)) {
    const double nrm = normalNorm(kind, index);
    double u_plus = 0.0;  // multiplier of the side being added
    for (;;) {
      if (result_.iterations >= options_.max_iterations) {
        message = "iteration limit reached";
        return QpStatus::kMaxIterations;
      }
      computeDirections(kind, index);
      const int q = q_;
      const double d2sq = tail2();
      const bool can_step = !dependent(d2sq, nrm);
      // largest dual step before an active inequality's multiplier hits zero
      double rmax = 0.0;
      for (int k = 0; k < q; ++k) rmax = std::max(rmax, std::abs(r_[k]));
      double t1 = kInf;
      int drop = -1;
      for (int k = 0; k < q; ++k) {
        if (act_eq_[k] || !(r_[k] > kRPositive * rmax)) continue;
        const double ratio = std::max(u_[k], 0.0) / r_[k];
        if (ratio < t1) {
          t1 = ratio;
          drop = k;
        }
      }
      if (!can_step && drop < 0) {
        message = "a violated constraint depends on active ones with the wrong sign";
        return QpStatus::kInfeasible;
      }
      ++result_.iterations;
      if (!can_step) {  // dual step only: x stays, one active side leaves
        u_.head(q) -= t1 * r_.head(q);
        u_plus += t1;
        dropActive(drop);
        continue;
      }
      const double t2 = -slack(kind, index) / d2sq;
      const double t = std::min(t1, t2);
      x_.head(n) += t * z_.head(n);
      u_.head(q) -= t * r_.head(q);
      u_plus += t;
      if (t2 <= t1) {
        appendActive(kind, index, u_plus, false);
        break;
      }
      dropActive(drop);
    }
  }
  return QpStatus::kOptimal;
}

// One step of iterative refinement at the optimum. x is built from many
// small steps, so with an ill-conditioned H its stationarity residual grows
// like eps * cond(H). Solving the active set's KKT system for the residuals
// with the factors already at hand (H^-1 = J J', J'N = [R; 0]) restores it:
//   r_s = H x + g - N u,  r_p = N'x - b,  dx = J y,
//   y1 = -R^-T r_p,  y2 = -(J' r_s)_2,  du = R^-1 (y1 + (J' r_s)_1).
void GoldfarbIdnaniSolver::refine() {
  const int n = n_;
  const int q = q_;
  const QpProblem& p = *p_;
  tmp_.head(n).noalias() = p.H * x_.head(n);
  tmp_.head(n) += p.g;
  for (int k = 0; k < q; ++k) {
    const QpRowKind kind = act_[k].kind;
    const int i = act_[k].index;
    if (isBoundKind(kind)) {
      tmp_[i] -= (kind == QpRowKind::kBoundUpper ? -u_[k] : u_[k]);
    } else {
      loadNormal(kind, i);
      tmp_.head(n) -= u_[k] * np_.head(n);
    }
  }
  d_.head(n).noalias() = J_.topLeftCorner(n, n).transpose() * tmp_.head(n);  // J' r_s
  for (int k = 0; k < q; ++k) {  // R' y1 = -r_p (forward substitution)
    double v = -slack(act_[k].kind, act_[k].index);
    for (int i = 0; i < k; ++i) v -= R_(i, k) * r_[i];
    r_[k] = v / R_(k, k);
  }
  for (int k = q; k < n; ++k) r_[k] = -d_[k];
  for (int k = q - 1; k >= 0; --k) {  // du = R^-1 (y1 + w1)
    double v = r_[k] + d_[k];
    for (int i = k + 1; i < q; ++i) v -= R_(k, i) * np_[i];
    np_[k] = v / R_(k, k);
  }
  z_.head(n).noalias() = J_.topLeftCorner(n, n) * r_.head(n);
  x_.head(n) += z_.head(n);
  for (int k = 0; k < q; ++k) {
    u_[k] += np_[k];
    if (!act_eq_[k]) u_[k] = std::max(u_[k], 0.0);
  }
}

// Whether x_ satisfies every equality, row side and bound (kVerify). The dual
// loop checks only inactive sides, and only against the iterate it built.
bool GoldfarbIdnaniSolver::primalFeasible() const {
  const QpProblem& p = *p_;
  const int n = n_;
  const auto x = x_.head(n);
  if (!x.allFinite()) return false;
  // v within [lo, hi] up to kVerify * (scale + |side|)
  auto holds = [](double v, double lo, double hi, double scale) {
    return (!hasLowerSide(lo) || v >= lo - kVerify * (scale + std::abs(lo))) &&
           (!hasUpperSide(hi) || v <= hi + kVerify * (scale + std::abs(hi)));
  };
  for (int i = 0; i < p.n_eq; ++i) {
    const double scale = eq_norm_[i] + p.A_eq.row(i).cwiseProduct(x.transpose()).cwiseAbs().sum();
    if (!holds(p.A_eq.row(i).dot(x), p.b_eq[i], p.b_eq[i], scale)) return false;
  }
  for (int i = 0; i < p.n_in; ++i) {
    if (row_type_[i] == kFree) continue;
    const double scale = row_norm_[i] + p.C.row(i).cwiseProduct(x.transpose()).cwiseAbs().sum();
    if (!holds(p.C.row(i).dot(x), p.c_lb[i], p.c_ub[i], scale)) return false;
  }
  for (int j = 0; j < n; ++j)
    if (!holds(x[j], p.x_lb[j], p.x_ub[j], 1.0 + std::abs(x[j]))) return false;
  return true;
}

// ---------------------------------------------------------------- solve

QpStatus GoldfarbIdnaniSolver::finish(QpStatus status, const char* message, Eigen::VectorXd& x) {
  const QpProblem& p = *p_;
  result_.status = status;
  result_.message = status == QpStatus::kOptimal ? "" : message;
  result_.active.clear();
  const bool sized = p.n >= 1 && p.n <= cap_n_;
  if (!sized) {
    result_.objective = 0.0;
    p_ = nullptr;
    return status;
  }
  const int n = p.n;
  if (x.size() != n) x.resize(n);  // allocates only if the caller did not size x
  if (status == QpStatus::kInvalidProblem) {
    x.setZero();
    result_.objective = 0.0;
    result_.y_eq.setZero();
    result_.y_in.setZero();
    result_.y_x.setZero();
    warm_.clear();
    p_ = nullptr;
    return status;
  }
  x = x_.head(n);
  result_.y_eq.head(p.n_eq).setZero();
  result_.y_in.head(p.n_in).setZero();
  result_.y_x.head(n).setZero();
  for (int k = 0; k < q_; ++k) {
    const QpActiveRow& a = act_[k];
    const double u = u_[k];
    switch (a.kind) {
      case QpRowKind::kEquality: result_.y_eq[a.index] = -u; break;
      case QpRowKind::kRowLower:
      case QpRowKind::kRowFixed: result_.y_in[a.index] = -u; break;
      case QpRowKind::kRowUpper: result_.y_in[a.index] = u; break;
      case QpRowKind::kBoundLower:
      case QpRowKind::kBoundFixed: result_.y_x[a.index] = -u; break;
      case QpRowKind::kBoundUpper: result_.y_x[a.index] = u; break;
    }
    result_.active.push_back(a);
  }
  tmp_.head(n).noalias() = p.H * x;
  result_.objective = 0.5 * x.dot(tmp_.head(n)) + p.g.dot(x);
  // remember the inequality sides of an optimum for the next warm start
  warm_.clear();
  if (status == QpStatus::kOptimal) {
    for (int k = 0; k < q_; ++k)
      if (!act_eq_[k]) warm_.push_back(act_[k]);
  }
  p_ = nullptr;
  return status;
}

QpStatus GoldfarbIdnaniSolver::solve(const QpProblem& problem, Eigen::VectorXd& x) {
  p_ = &problem;
  n_ = problem.n;
  q_ = 0;
  result_.iterations = 0;
  result_.warm_started = false;
  if (const char* bad = checkProblem()) return finish(QpStatus::kInvalidProblem, bad, x);
  const int n = n_;
  const double tol = options_.tolerance;
  x_.head(n).setZero();  // what an early infeasible exit reports

  // classify rows and bounds; contradicting sides are infeasible outright
  // row norms column by column (contiguous reads)
  eq_norm_.head(problem.n_eq).setZero();
  row_norm_.head(problem.n_in).setZero();
  for (int j = 0; j < n; ++j) {
    const double* a = problem.A_eq.col(j).data();
    for (int i = 0; i < problem.n_eq; ++i) eq_norm_[i] += a[i] * a[i];
    const double* c = problem.C.col(j).data();
    for (int i = 0; i < problem.n_in; ++i) row_norm_[i] += c[i] * c[i];
  }
  eq_norm_.head(problem.n_eq) = eq_norm_.head(problem.n_eq).cwiseSqrt();
  row_norm_.head(problem.n_in) = row_norm_.head(problem.n_in).cwiseSqrt();
  for (int i = 0; i < problem.n_in; ++i) {
    const double lb = problem.c_lb[i];
    const double ub = problem.c_ub[i];
    const double nrm = row_norm_[i];
    row_active_lo_[i] = row_active_up_[i] = 0;
    if (lb >= kQpInfinity || ub <= -kQpInfinity)
      return finish(QpStatus::kInfeasible, "a row has c_lb = +inf or c_ub = -inf", x);
    unsigned char t = kFree;
    if (hasLowerSide(lb)) t |= kHasLower;
    if (hasUpperSide(ub)) t |= kHasUpper;
    if (t == (kHasLower | kHasUpper)) {
      const double width_tol = tol * (nrm + std::max(std::abs(lb), std::abs(ub)));
      if (ub - lb < -width_tol)
        return finish(QpStatus::kInfeasible, "a row has c_lb > c_ub", x);
      if (ub - lb <= width_tol) t |= kFixed;
    }
    row_type_[i] = t;
  }
  for (int j = 0; j < n; ++j) {
    const double lb = problem.x_lb[j];
    const double ub = problem.x_ub[j];
    bnd_active_lo_[j] = bnd_active_up_[j] = 0;
    if (lb >= kQpInfinity || ub <= -kQpInfinity)
      return finish(QpStatus::kInfeasible, "a variable has x_lb = +inf or x_ub = -inf", x);
    unsigned char t = kFree;
    if (hasLowerSide(lb)) t |= kHasLower;
    if (hasUpperSide(ub)) t |= kHasUpper;
    if (t == (kHasLower | kHasUpper)) {
      const double width_tol = tol * (1.0 + std::max(std::abs(lb), std::abs(ub)));
      if (ub - lb < -width_tol)
        return finish(QpStatus::kInfeasible, "a variable has x_lb > x_ub", x);
      if (ub - lb <= width_tol) t |= kFixed;
    }
    bnd_type_[j] = t;
  }

  if (!factorize())
    return finish(QpStatus::kInvalidProblem, "H is not positive definite", x);
  coldStart();

  // equalities: A_eq rows, fixed rows, fixed variables
  for (int i = 0; i < problem.n_eq; ++i)
    if (addAsEquality(QpRowKind::kEquality, i) == AddOutcome::kInconsistent)
      return finish(QpStatus::kInfeasible, "the equality rows are inconsistent", x);
  for (int i = 0; i < problem.n_in; ++i)
    if ((row_type_[i] & kFixed) && addAsEquality(QpRowKind::kRowFixed, i) == AddOutcome::kInconsistent)
      return finish(QpStatus::kInfeasible, "a row with c_lb == c_ub contradicts the equalities", x);
  for (int j = 0; j < n; ++j)
    if ((bnd_type_[j] & kFixed) && addAsEquality(QpRowKind::kBoundFixed, j) == AddOutcome::kInconsistent)
      return finish(QpStatus::kInfeasible, "a fixed variable contradicts the equalities", x);

  result_.warm_started = tryWarmStart();
  const char* message = "";
  QpStatus status = dualLoop(message);
  if (status == QpStatus::kOptimal) {
    refine();
    if (!primalFeasible()) {
      status = QpStatus::kInfeasible;
      message = "the constraints are nearly inconsistent: the solve left a side violated";
    }
  }
  return finish(status, message, x);
}

}  // namespace handover::control
