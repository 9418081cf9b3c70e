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

  explicit Scenario(bool with_collision) {
    const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
    ctl = std::make_unique<Controller>(model, loadControllerConfig(defaultControllerConfigPath()));
    q = ctl->config().posture.target;
    ControlInputs in;
    in.q = q;
    ctl->reset(in);
    GraspOffset g;
    g.placement.linear() = expRotation(Vector3(M_PI, 0.0, 0.0));
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

void runBench(benchmark::State& state, bool with_collision) {
  Scenario sc(with_collision);
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

#ifdef HANDOVER_BENCH_COLLISION
void BM_ControlStepWithCollision(benchmark::State& state) { runBench(state, true); }
BENCHMARK(BM_ControlStepWithCollision)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace
