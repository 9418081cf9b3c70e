// One control cycle of the handover machine (inputs sanitised, force
// filtered, two interrupt conditions, the active path run), on the shipped
// config with a silent fake controller.
#include <benchmark/benchmark.h>

#include "tests/fsm/handover/fake_world.hpp"

namespace handover::fsm::test {
namespace {

void BM_StepWaiting(benchmark::State& state) {
  Rig rig;
  rig.ctl.record = false;
  rig.runFor(0.1);
  const HandoverInput in = rig.world.input(rig.ctl);
  HandoverInput cur = in;
  for (auto _ : state) {
    cur.time += 0.001;
    rig.fsm->step(cur);
    benchmark::DoNotOptimize(rig.fsm->activePath().data());
  }
}
BENCHMARK(BM_StepWaiting);

void BM_StepGrasping(benchmark::State& state) {
  Rig rig;
  rig.ctl.record = false;
  rig.world.moveHand(Vector3(0.55, 0.0, 0.30), 0.5);
  if (!rig.runUntilState("Grasp", 10.0)) state.SkipWithError("never reached Grasp");
  HandoverInput cur = rig.world.input(rig.ctl);
  cur.tcp_pose.translation().x() += 0.05;  // keep aligning: Grasp runs its checks every cycle
  for (auto _ : state) {
    cur.time += 0.001;
    rig.fsm->step(cur);
    benchmark::DoNotOptimize(rig.fsm->activePath().data());
  }
}
BENCHMARK(BM_StepGrasping);

}  // namespace
}  // namespace handover::fsm::test
