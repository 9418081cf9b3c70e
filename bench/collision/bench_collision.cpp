// BM_Distances: one control cycle of the collision stage (all pairs of
// config/collision.yaml: robot vs table, robot vs person (hand, arm, trunk),
// self pairs) with the person's arm next to the robot. Target: median <= 15 us.
#include <benchmark/benchmark.h>

#include <cmath>

#include "control/collision/collision_distances.hpp"
#include "control/constraints/collision_constraint.hpp"
#include "control/model/algorithms.hpp"

using namespace handover::control;

namespace {

const Model& model() {
  static const Model m = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return m;
}

Vector7 pose(int which) {
  Vector7 q;
  if (which == 0) {
    q << 0.0, -M_PI / 4, 0.0, -3 * M_PI / 4, 0.0, M_PI / 2, M_PI / 4;  // ready
  } else {
    q << 0.1, 0.35, 0.05, -1.9, 0.0, 2.2, M_PI / 4;  // reaching toward the person, hand low over the table
  }
  return q;
}

Isometry along(const Vector3& from, const Vector3& to) {
  Isometry X = Isometry::Identity();
  X.translation() = from;
  X.linear() = Quaternion::FromTwoVectors(Vector3::UnitZ(), to - from).toRotationMatrix();
  return X;
}

// the person's hand 8 cm in front of the TCP, forearm and upper arm behind it
CollisionEnvironment personNear(const Vector3& tcp) {
  CollisionEnvironment env;
  env.person_valid = true;
  env.hand.translation() = tcp + Vector3(0.08, 0.0, 0.0);
  const Vector3 wrist = env.hand.translation() + Vector3(0.06, 0.0, 0.0);
  const Vector3 elbow = wrist + Vector3(0.24, 0.05, -0.1);
  const Vector3 shoulder = elbow + Vector3(0.05, 0.05, 0.33);
  env.forearm = along(elbow, wrist);
  env.forearm_length = (wrist - elbow).norm();
  env.upper_arm = along(shoulder, elbow);
  env.upper_arm_length = (elbow - shoulder).norm();
  // the trunk under the shoulder (a right arm: the midline 0.175 m to its left), facing the robot
  env.trunk_valid = true;
  env.torso.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitZ()).toRotationMatrix();
  env.torso.translation() = Vector3(shoulder.x(), shoulder.y() - 0.175, -0.75);
  return env;
}

void BM_Distances(benchmark::State& state) {
  const Model& m = model();
  const CollisionModel cm = buildCollisionModel(m, loadCollisionConfig(defaultCollisionConfigPath()));
  CollisionData cd(cm);
  Data data(m);
  Vector7 v = Vector7::Constant(0.3);
  forwardKinematics(m, data, pose(static_cast<int>(state.range(0))), v);
  const CollisionEnvironment env = personNear(framePlacement(m, data, m.frameId("tcp")).translation());
  for (auto _ : state) {
    updateCollisions(cm, cd, m, data, env);
    benchmark::DoNotOptimize(cd.results.data());
  }
  state.counters["pairs"] = cm.numPairs();
  state.counters["narrow"] = cd.num_narrow;
  state.counters["active"] = cd.num_active;
}
BENCHMARK(BM_Distances)->ArgName("reaching")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Distances plus the damper rows, as the controller calls it every cycle.
void BM_CollisionConstraint(benchmark::State& state) {
  const Model& m = model();
  CollisionConstraint c(m, loadCollisionConfig(defaultCollisionConfigPath()));
  Data data(m);
  forwardKinematics(m, data, pose(1), Vector7::Constant(0.3));
  c.setEnvironment(personNear(framePlacement(m, data, m.frameId("tcp")).translation()));
  ControlContext ctx;
  ctx.model = &m;
  ctx.data = &data;
  Eigen::MatrixXd C(c.maxRows(), kNumVars);
  Eigen::VectorXd lb(c.maxRows()), ub(c.maxRows()), xl(kNumVars), xu(kNumVars);
  int rows = 0;
  for (auto _ : state) {
    rows = c.compute(ctx, C, lb, ub, xl, xu);
    benchmark::DoNotOptimize(rows);
  }
  state.counters["rows"] = rows;
}
BENCHMARK(BM_CollisionConstraint)->Unit(benchmark::kMicrosecond);

}  // namespace
