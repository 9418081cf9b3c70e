// Wall time of the limit guard (control/safety/limit_guard.hpp) alone, on the
// two paths it takes every control step: a command inside its bounds (the
// common case: the braking box, one torque product, no change) and one that
// drives every joint into its limits with more torque than the motors have
// (box clamps, Cholesky of M, the torque rounds). Target: <= 2 us (a small
// share of the 40 us control-step budget).
#include <benchmark/benchmark.h>

#include "control/controller_config.hpp"
#include "control/safety/limit_guard.hpp"

using namespace handover::control;

namespace {

void runGuard(benchmark::State& state, bool adversarial) {
  const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  LimitGuard guard(model, LimitGuardSettings(), 1e-3);
  Data data(model);
  Vector7 q = ControllerConfig().posture.target, qd;
  qd << 0.3, -0.2, 0.1, 0.4, -0.3, 0.2, 0.5;
  computeAll(model, data, q, qd);
  const Vector7 tau_ext = Vector7::Zero();
  Vector7 command;
  if (adversarial) command = Vector7::Constant(5e3);
  else command << 1.0, -2.0, 0.5, 3.0, -1.0, 2.0, -4.0;
  Vector7 qdd, tau;
  for (auto _ : state) {
    qdd = command;
    guard.apply(data, tau_ext, qdd, tau);
    benchmark::DoNotOptimize(tau.data());
  }
  state.counters["changed"] = guard.lastChanged() ? 1 : 0;
}

void BM_LimitGuardPassThrough(benchmark::State& state) { runGuard(state, false); }
BENCHMARK(BM_LimitGuardPassThrough)->Unit(benchmark::kMicrosecond);

void BM_LimitGuardActive(benchmark::State& state) { runGuard(state, true); }
BENCHMARK(BM_LimitGuardActive)->Unit(benchmark::kMicrosecond);

}  // namespace
