// Cost of one simulator cycle (scenes/sim): apply the command, one 1 ms
// MuJoCo step, read the arm state back. The arm is held near the ready pose
// by a small joint PD on the simulator's own state (torques of a few N m,
// no gravity model), so the state stays stationary however many iterations
// Google Benchmark runs and the figures do not depend on where the arm fell.
#include <benchmark/benchmark.h>

#include <cmath>

#include <Eigen/Geometry>

#include "scenes/sim/simulation.hpp"

namespace {

using namespace handover::sim;

Vector7 readyPose() {
  Vector7 q;
  q << 0.0, -M_PI / 4, 0.0, -3 * M_PI / 4, 0.0, M_PI / 2, M_PI / 4;
  return q;
}

// Weak PD: keeps the arm from falling through the table during a long run.
ArmCommand holdCommand(const ArmState& s, const Vector7& q_ref, double gripper_width) {
  static const Vector7 kp = (Vector7() << 600, 600, 600, 600, 250, 150, 50).finished();
  static const Vector7 kd = (Vector7() << 50, 50, 50, 50, 15, 8, 4).finished();
  ArmCommand c;
  c.tau = kp.cwiseProduct(q_ref - s.q) - kd.cwiseProduct(s.qd);
  c.gripper_width = gripper_width;
  c.gripper_force = 70.0;
  return c;
}

// Empty hand, fingers open, object on the table.
void BM_SimStep(benchmark::State& state) {
  Simulation sim;
  sim.load();
  const Vector7 q_ref = readyPose();
  sim.reset(q_ref, 0.08);
  ArmState s = sim.armState();
  for (auto _ : state) {
    sim.applyCommand(holdCommand(s, q_ref, 0.08));
    sim.step();
    s = sim.armState();
    benchmark::DoNotOptimize(s.q.data());
  }
  if (!s.q.allFinite()) state.SkipWithError("simulation diverged");
}
BENCHMARK(BM_SimStep);

// The fingers pinch a 0.5 kg cylinder (finger-object contacts every step).
void BM_SimStepHoldingObject(benchmark::State& state) {
  SimOptions options;
  options.object.shape = ObjectShape::Cylinder;
  options.object.size = {0.025, 0.12};
  options.object.mass = 0.5;
  Simulation sim;
  sim.load(options);
  const Vector7 q_ref = readyPose();
  // cylinder axis along the tcp x axis, pinched along the hand's y axis
  const Eigen::Isometry3d in_tcp(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  sim.reset(q_ref, 0.05, in_tcp);
  ArmState s = sim.armState();
  for (int i = 0; i < 300; ++i) {  // close the fingers and settle (not timed)
    sim.applyCommand(holdCommand(s, q_ref, 0.0));
    sim.step();
    s = sim.armState();
  }
  const auto held = [&sim] {
    const ContactReport r = sim.contacts();
    return r.left_finger_on_object && r.right_finger_on_object && !r.object_on_table;
  };
  if (!held()) {
    state.SkipWithError("the gripper does not hold the object after closing");
    return;
  }
  for (auto _ : state) {
    sim.applyCommand(holdCommand(s, q_ref, 0.0));
    sim.step();
    s = sim.armState();
    benchmark::DoNotOptimize(s.q.data());
  }
  // the figure is only meaningful if the object was held throughout
  if (!held()) state.SkipWithError("the object slipped out during the run");
}
BENCHMARK(BM_SimStepHoldingObject);

}  // namespace
