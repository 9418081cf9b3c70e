// The way of a large turn with a joint plan (control/tasks/planned_turn.hpp):
// the lift of the TCP's orientation along the joint path plus the error, as
// the tracking task runs it when a plan arrives (between plans a step only
// keeps the TCP's quaternion sign continuous: PlannedTurnLift). Arg: the summed
// joint motion to the plan in quarter turns, so the number of orientation-
// only kinematics evaluated (1 typical; 11 from the middle of the range to
// its corner, 22 corner to corner).
#include <benchmark/benchmark.h>

#include <cmath>

#include "control/model/algorithms.hpp"
#include "control/tasks/planned_turn.hpp"

using namespace handover::control;

namespace {

void BM_PlannedTurn(benchmark::State& state) {
  const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  const int tcp = model.frameId("tcp");
  const int steps = static_cast<int>(state.range(0));
  // from the middle of the range toward its corner, summed motion steps * pi / 2 (just below)
  const Vector7 middle = 0.5 * (model.q_min + model.q_max);
  const Vector7 span = 0.5 * (model.q_max - model.q_min);
  const double scale = std::min(1.0, (steps * 0.5 * M_PI - 1e-6) / span.sum());
  const Vector7 q = middle, q_plan = middle + scale * span;
  const Quaternion now(frameRotation(model, tcp, q));
  const Quaternion target(frameRotation(model, tcp, q_plan));
  bool long_way = false;
  for (auto _ : state) {
    const Quaternion plan = planOrientationAlongJointPath(model, tcp, q, now, q_plan);
    benchmark::DoNotOptimize(plannedTurnError(now, target, plan, long_way));
  }
  state.counters["kinematics"] = steps;
}
BENCHMARK(BM_PlannedTurn)->Arg(1)->Arg(4)->Arg(11)->Unit(benchmark::kNanosecond);

}  // namespace
