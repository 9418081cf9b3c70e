// Wall time of one controller step (computeAll, task rows, QP assembly,
// solve, observed-object integration, torques) on a kinematic simulation of a
// person bringing an object toward the robot, so the active sets and warm
// starts change as in a real run. Target: <= 40 us per step.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "control/controller.hpp"
#include "control/so3.hpp"
#ifdef HANDOVER_BENCH_COLLISION
#include "control/constraints/collision_constraint.hpp"
#endif

using namespace handover::control;

namespace {

struct Scenario {
  std::unique_ptr<Controller> ctl;
  Vector7 q, v = Vector7::Zero();
  double t = 0.0;
  Isometry object = Isometry::Identity();
#ifdef HANDOVER_BENCH_COLLISION
  std::shared_ptr<CollisionConstraint> collision;
#endif

  /// `with_joint_plan`: the offset carries the grasp planner's configuration
  /// (as in Approach and Present): the first step lifts the TCP's orientation
  /// along the joint path to it, every step picks the turn's way from that
  /// lift (planned_turn.hpp).
  explicit Scenario(bool with_collision, bool with_joint_plan = false) {
    const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
    ctl = std::make_unique<Controller>(model, loadControllerConfig(defaultControllerConfigPath()));
    q = ctl->config().posture.target;
    ControlInputs in;
    in.q = q;
    ctl->reset(in);
    GraspOffset g;
    g.placement.linear() = expRotation(Vector3(M_PI, 0.0, 0.0));
    if (with_joint_plan) {
      // a plan 0.3-0.6 rad from the start on every joint: the typical 2-step lift
      g.has_joint_plan = true;
      g.joint_plan = q + (Vector7() << 0.3, -0.4, 0.5, 0.3, -0.6, 0.4, 0.5).finished();
    }
    ctl->setGraspOffset(g);
#ifdef HANDOVER_BENCH_COLLISION
    if (with_collision) {
      collision = std::make_shared<CollisionConstraint>(ctl->model(), loadCollisionConfig(defaultCollisionConfigPath()));
      ctl->formulation().addConstraint(collision);
    }
#else
    (void)with_collision;
#endif
  }

  // the person's hand: a slow loop in front of the robot
  void moveObject() {
    const double s = 0.5 * t;
    object.translation() = Vector3(0.55 + 0.1 * std::cos(s), 0.15 * std::sin(s), 0.3 + 0.05 * std::sin(2 * s));
    object.linear() = expRotation(Vector3(0.0, 0.0, 0.3 * std::sin(s)));
#ifdef HANDOVER_BENCH_COLLISION
    if (collision) {
      CollisionEnvironment env;
      env.person_valid = true;
      env.hand = object;
      env.forearm.translation() = object.translation() + Vector3(0.27, 0.0, -0.05);
      env.forearm.linear() = expRotation(Vector3(0.0, -M_PI / 2, 0.0));
      env.upper_arm.translation() = env.forearm.translation() + Vector3(0.1, 0.0, 0.3);
      env.upper_arm.linear() = expRotation(Vector3(0.0, M_PI, 0.0));
      collision->setEnvironment(env);
    }
#endif
  }

  void step() {
    moveObject();
    ctl->setObservationTarget(object, true);
    ControlInputs in;
    in.time = t;
    in.q = q;
    in.qd = v;
    ctl->step(in);
    const double dt = ctl->config().period;
    v += ctl->lastQdd() * dt;
    q += v * dt;
    t += dt;
  }
};

void runBench(benchmark::State& state, bool with_collision, bool with_joint_plan = false) {
  Scenario sc(with_collision, with_joint_plan);
  for (int k = 0; k < 500; ++k) sc.step();  // past the start transient
  long fallbacks0 = sc.ctl->fallbackCount();
  for (auto _ : state) {
    sc.step();
    benchmark::DoNotOptimize(sc.ctl->lastTau().data());
  }
  state.counters["qp_iterations"] = sc.ctl->lastIterations();
  state.counters["fallbacks"] = static_cast<double>(sc.ctl->fallbackCount() - fallbacks0);
  state.counters["rows"] = sc.ctl->problem().n_in;
}

void BM_ControlStep(benchmark::State& state) { runBench(state, false); }
BENCHMARK(BM_ControlStep)->Unit(benchmark::kMicrosecond);

void BM_ControlStepWithJointPlan(benchmark::State& state) { runBench(state, false, true); }
BENCHMARK(BM_ControlStepWithJointPlan)->Unit(benchmark::kMicrosecond);

#ifdef HANDOVER_BENCH_COLLISION
void BM_ControlStepWithCollision(benchmark::State& state) { runBench(state, true); }
BENCHMARK(BM_ControlStepWithCollision)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace
