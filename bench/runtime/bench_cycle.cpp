// BM_Cycle: wall time of one whole control cycle (runtime::HandoverCycle::
// step: perception, state machine input, state machine, observation target,
// collision environment, controller step) on the shipped configs, while a
// person brings an object toward the robot and holds it there (60 Hz pose
// samples). The arm integrates the QP's accelerations (no simulator), so the
// state machine leaves its wait state and the QP's active set changes as in a
// run. A fresh cycle starts every 8 s of cycle time (untimed), so the
// measurement covers waiting, approaching and lining up, not only a final
// resting state. Target: p99 of the app's control_step_us <= 50 us.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "control/so3.hpp"
#include "runtime/handover_cycle.hpp"

using namespace handover;

namespace {

/// The person's hand: from 0.9 m in front of the robot to 0.55 m in 1.5 s
/// (minimum jerk), then still; samples at 60 Hz.
class OfferingPerson : public perception::PoseSource {
 public:
  bool poll(double now, perception::PoseSample& out) override {
    if (now + 1e-9 < next_) return false;
    out.stamp = next_;
    next_ += 1.0 / 60.0;
    const double s = std::min(out.stamp / 1.5, 1.0);
    const double phase = s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
    Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
    hand.translation() = Eigen::Vector3d(0.9 - 0.35 * phase, 0.1 - 0.1 * phase, 0.2 + 0.1 * phase);
    Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();
    forearm.translation() = hand.translation() + Eigen::Vector3d(0.27, 0.0, -0.05);
    forearm.linear() = control::expRotation(control::Vector3(0.0, -M_PI / 2, 0.0));
    Eigen::Isometry3d upper_arm = Eigen::Isometry3d::Identity();
    upper_arm.translation() = forearm.translation() + Eigen::Vector3d(0.1, 0.0, 0.3);
    upper_arm.linear() = control::expRotation(control::Vector3(0.0, M_PI, 0.0));
    out.hand = perception::Pose::fromIsometry(hand);
    out.forearm = perception::Pose::fromIsometry(forearm);
    out.upper_arm = perception::Pose::fromIsometry(upper_arm);
    return true;
  }

 private:
  double next_ = 0.0;
};

struct Run {
  std::unique_ptr<runtime::HandoverCycle> cycle;
  OfferingPerson person;
  io::ArmState arm;
  double t = 0.0;

  explicit Run(const runtime::CycleSettings& s) : cycle(std::make_unique<runtime::HandoverCycle>(s)) {
    arm.q = s.controller.posture.target;
    arm.finger_width = s.gripper_open_width;
    arm.wrench.head<3>() = Eigen::Vector3d(0.0, 0.0, 0.73 * 9.81);  // the hand hanging on the sensor
    cycle->start(arm, false);
  }
  void step() {
    arm.time = t;
    cycle->step(t, arm, person);
    const double dt = cycle->controller().config().period;
    arm.qd += cycle->controller().lastQdd() * dt;  // semi-implicit Euler, as the controller's integrator
    arm.q += arm.qd * dt;
    t += dt;
  }
};

runtime::CycleSettings benchSettings() {
  runtime::CycleSettings s = runtime::defaultCycleSettings();
  s.object.mass = 0.3;
  s.object.grasp_in_object.linear() = control::expRotation(control::Vector3(M_PI, 0.0, 0.0));
  s.object.com_in_tcp = s.object.grasp_in_object.inverse().translation();
  s.object_grasp.placement = s.object.grasp_in_object;
  s.estimator.hand_T_object.translation() = Eigen::Vector3d(0.0, 0.0, 0.05);
  return s;
}

void BM_Cycle(benchmark::State& state) {
  const runtime::CycleSettings settings = benchSettings();
  auto run = std::make_unique<Run>(settings);
  for (auto _ : state) {
    if (run->t >= 8.0) {
      state.PauseTiming();
      run = std::make_unique<Run>(settings);
      state.ResumeTiming();
    }
    run->step();
    benchmark::DoNotOptimize(run->cycle->command());
  }
  state.counters["fallbacks"] = static_cast<double>(run->cycle->controller().fallbackCount());
  state.SetLabel(run->cycle->machine().activePath());  // where the last run's state machine got to
}
BENCHMARK(BM_Cycle)->Unit(benchmark::kMicrosecond)->MinTime(2.0);

}  // namespace
