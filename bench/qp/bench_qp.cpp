// Speed of the Goldfarb-Idnani solver on the controller-shaped QP
// (controller_like_qp.hpp): 13 variables, 27 two-sided/one-sided rows, bounds.
//   BM_QpSolve      warm-started, along a periodic sequence of slightly
//                   perturbed problems (consecutive control cycles)
//   BM_QpSolveCold  the same sequence, every solve from scratch
//   BM_QpRelaxedSolve  the same problems with their collision-like rows soft
//                   and one demanding more than the torque limits allow: the
//                   hard solve that fails plus SoftRowRelaxation's two phases
//                   (what a cycle costs when a person moves in too fast)
// Counters: iterations and active-set size per solve (means).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "bench/qp/controller_like_qp.hpp"
#include "control/qp/goldfarb_idnani.hpp"
#include "control/qp/soft_row_relaxation.hpp"

namespace {

using handover::control::GoldfarbIdnaniSolver;
using handover::control::QpProblem;
using handover::control::QpSolverOptions;
using handover::control::QpStatus;

constexpr int kSequence = 256;  // problems per period of the reference motion

const std::vector<QpProblem>& sequence() {
  static const std::vector<QpProblem> problems = [] {
    std::vector<QpProblem> v(kSequence);
    for (int k = 0; k < kSequence; ++k) {
      v[k].reserve(13, 0, 27);
      handover::bench::controllerLikeQp(2.0 * M_PI * k / kSequence, v[k]);
    }
    return v;
  }();
  return problems;
}

void run(benchmark::State& state, bool warm) {
  const std::vector<QpProblem>& problems = sequence();
  QpSolverOptions options;
  options.warm_start = warm;
  GoldfarbIdnaniSolver solver(options);
  solver.reserve(13, 0, 27);
  Eigen::VectorXd x(13);
  // one pass first, so the warm start is in steady state and failures show up
  for (const QpProblem& p : problems) {
    if (solver.solve(p, x) != QpStatus::kOptimal) {
      state.SkipWithError("controller-like QP not solved");
      return;
    }
  }
  long k = 0, iterations = 0, active = 0, failures = 0;
  for (auto _ : state) {
    const QpStatus st = solver.solve(problems[k % kSequence], x);
    benchmark::DoNotOptimize(x.data());
    failures += st != QpStatus::kOptimal;
    iterations += solver.result().iterations;
    active += static_cast<long>(solver.result().active.size());
    ++k;
  }
  if (failures > 0) state.SkipWithError("a solve failed");
  state.counters["iterations"] = benchmark::Counter(static_cast<double>(iterations) / k);
  state.counters["active"] = benchmark::Counter(static_cast<double>(active) / k);
}

void BM_QpSolve(benchmark::State& state) { run(state, true); }

// Harder than the controller: random 13 variables, 7 equalities, 40 two-sided
// rows and bounds with many active sides, always from scratch.
void BM_QpSolveColdRandom13x7x40(benchmark::State& state) {
  std::mt19937 rng(4);
  std::normal_distribution<double> nd(0.0, 1.0);
  std::uniform_real_distribution<double> ud(0.0, 1.0);
  QpProblem p;
  p.reserve(13, 7, 40);
  p.n_eq = 7;
  p.n_in = 40;
  Eigen::MatrixXd M = Eigen::MatrixXd::NullaryExpr(13, 13, [&] { return nd(rng); });
  p.H = M.transpose() * M + 0.1 * Eigen::MatrixXd::Identity(13, 13);
  p.g = Eigen::VectorXd::NullaryExpr(13, [&] { return 30.0 * nd(rng); });
  const Eigen::VectorXd xf = Eigen::VectorXd::NullaryExpr(13, [&] { return nd(rng); });
  p.A_eq = Eigen::MatrixXd::NullaryExpr(7, 13, [&] { return nd(rng); });
  p.b_eq = p.A_eq * xf;
  p.C = Eigen::MatrixXd::NullaryExpr(40, 13, [&] { return nd(rng); });
  const Eigen::VectorXd cx = p.C * xf;
  for (int i = 0; i < 40; ++i) {
    p.c_lb[i] = cx[i] - ud(rng);
    p.c_ub[i] = cx[i] + ud(rng);
  }
  for (int j = 0; j < 13; ++j) {
    p.x_lb[j] = xf[j] - ud(rng);
    p.x_ub[j] = xf[j] + ud(rng);
  }
  QpSolverOptions options;
  options.warm_start = false;
  GoldfarbIdnaniSolver solver(options);
  solver.reserve(13, 7, 40);
  Eigen::VectorXd x(13);
  if (solver.solve(p, x) != QpStatus::kOptimal) {
    state.SkipWithError("random QP not solved");
    return;
  }
  for (auto _ : state) {
    solver.solve(p, x);
    benchmark::DoNotOptimize(x.data());
  }
  state.counters["iterations"] = solver.result().iterations;
  state.counters["active"] = static_cast<double>(solver.result().active.size());
}
void BM_QpSolveCold(benchmark::State& state) { run(state, false); }

void BM_QpRelaxedSolve(benchmark::State& state) {
  using handover::control::SoftRowRelaxation;
  std::vector<QpProblem> problems = sequence();
  for (QpProblem& p : problems) {
    p.soft_in.segment(7, 20).setConstant(1);  // the collision-like rows
    p.c_lb[7] = 1e4;                          // an escape no torque can give
  }
  GoldfarbIdnaniSolver solver;
  solver.reserve(SoftRowRelaxation::solverVars(13), 0, SoftRowRelaxation::solverRowsIn(27));
  SoftRowRelaxation relaxation;
  relaxation.reserve(13, 0, 27);
  Eigen::VectorXd x(13);
  long k = 0, failures = 0, iterations = 0;
  double slack = 0.0;
  for (auto _ : state) {
    const QpProblem& p = problems[k % kSequence];
    QpStatus st = solver.solve(p, x);
    if (st == QpStatus::kInfeasible) st = relaxation.solve(p, solver, x);
    benchmark::DoNotOptimize(x.data());
    failures += st != QpStatus::kOptimal;
    iterations += relaxation.iterations();
    slack += relaxation.slack();
    ++k;
  }
  if (failures > 0) state.SkipWithError("a relaxed solve failed");
  state.counters["iterations"] = benchmark::Counter(static_cast<double>(iterations) / k);
  state.counters["slack"] = benchmark::Counter(slack / k);
}

BENCHMARK(BM_QpSolve)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_QpSolveCold)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_QpRelaxedSolve)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_QpSolveColdRandom13x7x40)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace
