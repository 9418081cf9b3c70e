// After reserve(), solving allocates nothing: 1000 solves of changing
// problems (warm and cold paths, varying row counts, infeasible and invalid
// ones in between) run while every heap allocation is counted. Both the C++
// allocation functions and the C allocator (Eigen allocates with malloc) are
// replaced in this binary by counting wrappers.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <cstdio>
#include <random>

#include "control/qp/goldfarb_idnani.hpp"
#include "control/qp/soft_row_relaxation.hpp"
#include "tests/control/qp/qp_test_problems.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
inline void note() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
}
}  // namespace

// --- C allocator: forward to glibc's implementation, counting calls
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t size) {
  note();
  return __libc_malloc(size);
}
void* calloc(std::size_t n, std::size_t size) {
  note();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t size) {
  note();
  return __libc_realloc(p, size);
}
void free(void* p) { __libc_free(p); }
}

// --- C++ allocation functions
void* operator new(std::size_t size) {
  note();
  if (void* p = __libc_malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  note();
  return __libc_malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t& t) noexcept {
  return operator new(size, t);
}
void* operator new(std::size_t size, std::align_val_t al) {
  note();
  if (void* p = __libc_memalign(static_cast<std::size_t>(al), size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t al) { return operator new(size, al); }
void operator delete(void* p) noexcept { __libc_free(p); }
void operator delete[](void* p) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }

namespace handover::control {
namespace {

TEST(QpAllocation, CounterSeesEigenAndNewAllocations) {
  // the counter must be able to fail: it sees a dynamic Eigen vector and new
  g_allocations = 0;
  g_counting = true;
  Eigen::VectorXd v(50);
  auto* i = new int(3);
  g_counting = false;
  delete i;
  v.setZero();
  EXPECT_GE(g_allocations.load(), 2);
}

TEST(QpAllocation, ThousandSolvesAfterReserveAllocateNothing) {
  std::mt19937 rng(99);
  test::RandomQpSpec spec;
  spec.n = 13;
  spec.n_eq = 7;
  spec.n_in = 40;
  spec.g_scale = 30.0;
  QpProblem base;
  test::makeRandomQp(spec, rng, base);
  QpProblem p = base;
  GoldfarbIdnaniSolver solver;
  solver.reserve(p.n, p.capacityEq(), p.capacityIn());
  QpSolverOptions cold_options;
  cold_options.warm_start = false;
  const QpSolverOptions warm_options;
  Eigen::VectorXd x(p.n);
  int optimal = 0, infeasible = 0, invalid = 0, warm = 0;

  g_allocations = 0;
  g_counting = true;
  for (int k = 0; k < 1000; ++k) {
    const double t = 0.01 * k;
    for (int j = 0; j < p.n; ++j) p.g[j] = base.g[j] * (1.0 + 0.5 * std::sin(t + j));
    // lower sides only move down, so the problem stays feasible
    for (int i = 0; i < spec.n_in; ++i) p.c_lb[i] = base.c_lb[i] - 0.2 * (1.0 + std::sin(t + i));
    p.n_in = 30 + k % 11;           // rows in use vary up to the capacity
    p.n_eq = k % 50 == 0 ? 3 : 7;
    solver.setOptions(k % 7 == 0 ? cold_options : warm_options);
    const bool make_infeasible = k % 97 == 0;
    const bool make_invalid = k % 89 == 0;
    if (make_infeasible) p.x_lb[0] = p.x_ub[0] + 1.0;
    if (make_invalid) p.g[3] = std::numeric_limits<double>::quiet_NaN();
    const long before = g_allocations.load();
    const QpStatus st = solver.solve(p, x);
    if (g_allocations.load() != before && std::getenv("QP_ALLOC_DEBUG")) {
      g_counting = false;
      std::printf("k=%d status=%s warm=%d allocs=%ld\n", k, toString(st), solver.result().warm_started, g_allocations.load() - before);
      g_counting = true;
    }
    switch (st) {
      case QpStatus::kOptimal: ++optimal; break;
      case QpStatus::kInfeasible: ++infeasible; break;
      case QpStatus::kInvalidProblem: ++invalid; break;
      case QpStatus::kMaxIterations: break;
    }
    warm += solver.result().warm_started;
    p.x_lb[0] = base.x_lb[0];
    p.g[3] = base.g[3];
  }
  g_counting = false;

  EXPECT_EQ(g_allocations.load(), 0);
  // the loop really exercised the solver's paths
  EXPECT_GT(optimal, 950);
  EXPECT_GT(infeasible, 5);
  EXPECT_GT(invalid, 5);
  EXPECT_GT(warm, 500);
}

TEST(QpAllocation, RelaxedSolvesAfterReserveAllocateNothing) {
  // infeasible problems whose soft rows conflict, relaxed every time
  std::mt19937 rng(7);
  test::RandomQpSpec spec;
  spec.n = 13;
  spec.n_eq = 0;
  spec.n_in = 30;
  QpProblem p;
  test::makeRandomQp(spec, rng, p);
  GoldfarbIdnaniSolver solver;
  solver.reserve(SoftRowRelaxation::solverVars(p.n), p.capacityEq(),
                 SoftRowRelaxation::solverRowsIn(p.capacityIn()));
  SoftRowRelaxation relaxation;
  relaxation.reserve(p.n, p.capacityEq(), p.capacityIn());
  Eigen::VectorXd x(p.n);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int relaxed = 0;

  g_allocations = 0;
  g_counting = true;
  for (int k = 0; k < 200; ++k) {
    // rows 0 and 1 demand opposite things of x_{k mod n}
    p.C.topRows(2).setZero();
    p.C(0, k % p.n) = 1.0;
    p.C(1, k % p.n) = 1.0;
    p.c_lb[0] = 1.0 + 0.01 * k;
    p.c_ub[0] = kInf;
    p.c_lb[1] = -kInf;
    p.c_ub[1] = -1.0;
    p.soft_in.setZero();
    p.soft_in[0] = p.soft_in[1] = 1;
    p.n_in = 20 + k % 11;
    if (relaxation.solve(p, solver, x) == QpStatus::kOptimal) ++relaxed;
  }
  g_counting = false;

  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_GT(relaxed, 150);  // the loop exercised both phases
}

}  // namespace
}  // namespace handover::control
