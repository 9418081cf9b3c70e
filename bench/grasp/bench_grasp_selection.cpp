// Cost of grasp selection (docs/grasp_selection.md). Target: a full
// selection over 24 candidates with warm starts well under 1 ms, so that it
// can run at the sensor rate (60 Hz).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "control/grasp/chain_kinematics.hpp"
#include "control/grasp/grasp_selector.hpp"
#include "control/grasp/shape_grasps.hpp"
#include "control/grasp/upright_placement.hpp"

namespace {

using namespace handover::control;
using namespace handover::control::grasp;

const Model& pandaModel() {
  static const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return model;
}

const GraspSelectionConfig& shippedConfig() {
  static const GraspSelectionConfig config =
      loadGraspSelectionConfig(std::string(HANDOVER_SOURCE_DIR) + "/config/grasp_selection.yaml");
  return config;
}

Vector7 ready() {
  Vector7 q;
  q << 0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398;
  return q;
}

Isometry tcpPose(const Model& model, const Vector7& q) {
  ChainPoses poses;
  chainPoses(model, q, poses);
  return chainFramePose(model, poses, model.frameId("tcp"));
}

// random configurations 0.05 rad inside the limits and their TCP poses
struct RandomTargets {
  static constexpr int kN = 256;
  std::vector<Vector7> q;
  std::vector<Isometry> X;
  RandomTargets() {
    const Model& m = pandaModel();
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < kN; ++k) {
      Vector7 qk;
      for (int i = 0; i < kArmDofs; ++i) qk[i] = m.q_min[i] + 0.05 + u(rng) * (m.q_max[i] - m.q_min[i] - 0.1);
      q.push_back(qk);
      X.push_back(tcpPose(m, qk));
    }
  }
};

void BM_ChainKinematics(benchmark::State& state) {
  const Model& model = pandaModel();
  const RandomTargets t;
  const int tcp = model.frameId("tcp");
  ChainPoses poses;
  Matrix6x7 J;
  int k = 0;
  for (auto _ : state) {
    chainPoses(model, t.q[k], poses);
    const Isometry X = chainFramePose(model, poses, tcp);
    chainFrameJacobian(model, poses, tcp, J);
    benchmark::DoNotOptimize(X.data());
    benchmark::DoNotOptimize(J.data());
    k = (k + 1) % RandomTargets::kN;
  }
}
BENCHMARK(BM_ChainKinematics);

// one IK solve from the previous solution after the target moved 5 mm and 1 degree
void BM_IkWarm(benchmark::State& state) {
  const Model& model = pandaModel();
  const RandomTargets t;
  const int tcp = model.frameId("tcp");
  std::vector<Isometry> moved(RandomTargets::kN);
  for (int k = 0; k < RandomTargets::kN; ++k) {
    moved[k] = Eigen::Translation3d(0.003, -0.003, 0.0025) * t.X[k] *
               Eigen::AngleAxisd(M_PI / 180.0, Vector3(1, 1, 0).normalized());
  }
  int k = 0, converged = 0, iterations = 0, solves = 0;
  for (auto _ : state) {
    const IkResult r = solveIk(model, tcp, moved[k], t.q[k], shippedConfig().ik);
    converged += r.converged;
    iterations += r.iterations;
    ++solves;
    benchmark::DoNotOptimize(r.q.data());
    k = (k + 1) % RandomTargets::kN;
  }
  state.counters["converged"] = static_cast<double>(converged) / solves;
  state.counters["iterations"] = static_cast<double>(iterations) / solves;
}
BENCHMARK(BM_IkWarm);

// a random reachable pose from the current q (ready) then the shipped seeds:
// the cold start, and the success rate on random targets
void BM_IkColdMultiStart(benchmark::State& state) {
  const Model& model = pandaModel();
  const RandomTargets t;
  const int tcp = model.frameId("tcp");
  std::vector<Vector7> seeds{ready()};
  seeds.insert(seeds.end(), shippedConfig().seeds.begin(), shippedConfig().seeds.end());
  int k = 0, converged = 0, solves = 0;
  double worst_pos = 0.0, worst_rot = 0.0;
  for (auto _ : state) {
    const IkResult r = solveIkMultiStart(model, tcp, t.X[k], seeds.data(), static_cast<int>(seeds.size()), shippedConfig().ik);
    if (r.converged) {
      ++converged;
      worst_pos = std::max(worst_pos, r.position_error);
      worst_rot = std::max(worst_rot, r.orientation_error);
    }
    ++solves;
    benchmark::DoNotOptimize(r.q.data());
    k = (k + 1) % RandomTargets::kN;
  }
  state.counters["converged"] = static_cast<double>(converged) / solves;
  state.counters["worst_pos_mm"] = worst_pos * 1e3;
  state.counters["worst_rot_deg"] = worst_rot * 180.0 / M_PI;
}
BENCHMARK(BM_IkColdMultiStart);

// issue 12's bottle taken from the side: 12 turns about its axis x 2 twins
GraspSpec bottleSideGrasp() {
  GraspSpec s;
  s.placement.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  s.has_free_axis = true;
  return s;
}

// the object as a person brings it: 0.2 m/s sideways, a slow sway, sampled at 60 Hz
Isometry swayingObject(int k) {
  const double t = k / 60.0;
  Isometry X = Isometry::Identity();
  X.translation() = Vector3(0.55 + 0.03 * std::sin(1.3 * t), 0.15 * std::sin(0.9 * t), 0.30 + 0.02 * std::sin(2.1 * t));
  X.linear() = Eigen::AngleAxisd(0.1 * std::sin(0.7 * t), Vector3::UnitX()).toRotationMatrix();
  return X;
}

// `updates` selections of a moving object after a cold first update (not measured)
void runMovingSelection(benchmark::State& state, int cold_solves_per_update,
                        const std::vector<GraspSpec>& specs = {bottleSideGrasp()}) {
  const Model& model = pandaModel();
  GraspSelectionConfig cfg = shippedConfig();
  cfg.cold_solves_per_update = cold_solves_per_update;
  GraspSelector selector(model, specs, cfg);
  const Vector7 q_now = ready();
  int k = 0;
  selector.update(swayingObject(k++), q_now);
  long iterations = 0, updates = 0, switches = 0, reachable = 0;
  for (auto _ : state) {
    const GraspChoice& c = selector.update(swayingObject(k++), q_now);
    for (const CandidateEvaluation& e : selector.evaluations()) {
      iterations += e.iterations;
      reachable += e.feasible;
    }
    switches += c.switched;
    ++updates;
    benchmark::DoNotOptimize(c.q_grasp.data());
  }
  state.counters["candidates"] = static_cast<double>(selector.candidates().size());
  state.counters["reachable"] = static_cast<double>(reachable) / updates;
  state.counters["ik_iterations"] = static_cast<double>(iterations) / updates;
  state.counters["switches"] = static_cast<double>(switches);
}

// one update at the sensor rate with the shipped config: warm IK of every
// reachable candidate (grasp and pre-grasp), one-seed retries of at most
// `cold_solves_per_update` unreachable ones, scores and hysteresis
void BM_SelectionMovingObject(benchmark::State& state) { runMovingSelection(state, shippedConfig().cold_solves_per_update); }
BENCHMARK(BM_SelectionMovingObject);

// the same over the declared grasp and every family the bottle's shape allows
// (side, 45 degrees, top: 84 candidates), as runtime/grasp_planning plans
void BM_SelectionWithShapeFamilies(benchmark::State& state) {
  // what the handover cycle plans over: the declared grasp and the bottle's families
  std::vector<GraspSpec> specs{bottleSideGrasp()};
  for (const GraspSpec& g : shapeGraspSpecs(PrimitiveShape::kCylinder, {0.03, 0.20})) specs.push_back(g);
  runMovingSelection(state, shippedConfig().cold_solves_per_update, specs);
}
BENCHMARK(BM_SelectionWithShapeFamilies);

// the same for a 5 x 6 x 20 cm box declared from the top: its families through the middle of
// each face and by either end of the long edge (16 specs; 34 candidates with the twins)
void BM_SelectionBoxWithShapeFamilies(benchmark::State& state) {
  GraspSpec top;
  top.placement.translation() = Vector3(0.0, 0.0, 0.06);
  top.placement.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  std::vector<GraspSpec> specs{top};
  for (const GraspSpec& g : shapeGraspSpecs(PrimitiveShape::kBox, {0.05, 0.06, 0.20})) specs.push_back(g);
  runMovingSelection(state, shippedConfig().cold_solves_per_update, specs);
}
BENCHMARK(BM_SelectionBoxWithShapeFamilies);

// the same with every seed retried for every unreachable candidate in every
// update (cold_solves_per_update: 0): what the retry budget saves
void BM_SelectionRetryingAllSeeds(benchmark::State& state) { runMovingSelection(state, 0); }
BENCHMARK(BM_SelectionRetryingAllSeeds)->Unit(benchmark::kMillisecond);

// the first update for a new object: every candidate solved from every seed
void BM_SelectionFirstUpdate(benchmark::State& state) {
  const Model& model = pandaModel();
  GraspSelector selector(model, {bottleSideGrasp()}, shippedConfig());
  const Vector7 q_now = ready();
  for (auto _ : state) {
    selector.reset();
    const GraspChoice& c = selector.update(swayingObject(0), q_now);
    benchmark::DoNotOptimize(c.q_grasp.data());
  }
}
BENCHMARK(BM_SelectionFirstUpdate)->Unit(benchmark::kMillisecond);

// stow after a side grasp: upright, any turn about the vertical, near the stow point
void BM_UprightPlacement(benchmark::State& state) {
  const Model& model = pandaModel();
  HeldObject held;
  held.object_in_tcp.linear() = Eigen::AngleAxisd(-M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  int solves = 0, calls = 0;
  for (auto _ : state) {
    const UprightPlacement p = findUprightPlacement(model, held, Vector3(0.35, 0.0, 0.40), ready(), shippedConfig());
    solves += p.ik_solves;
    ++calls;
    benchmark::DoNotOptimize(p.q.data());
  }
  state.counters["ik_solves"] = static_cast<double>(solves) / calls;
}
BENCHMARK(BM_UprightPlacement)->Unit(benchmark::kMillisecond);

// the give's wait at the ready pose, scored against a receiver: their forearm,
// upper arm, a torso of two capsules, the head, the free arm and the reach
// from the shoulder to the object's side (GraspPlanning::uprightPlacement)
void BM_UprightPlacementForAReceiver(benchmark::State& state) {
  const Model& model = pandaModel();
  HeldObject held;
  held.object_in_tcp.linear() = Eigen::AngleAxisd(-M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  const Vector3 shoulder(0.88, -0.28, 0.69), place(0.44, 0.0, 0.40);
  auto capsule = [](const Vector3& a, const Vector3& b, double r) {
    ObstacleCapsule c;
    c.a = a;
    c.b = b;
    c.radius = r;
    return c;
  };
  std::vector<ObstacleCapsule> person = {
      capsule(Vector3(0.77, -0.45, 0.39), Vector3(0.73, -0.24, 0.20), 0.035),
      capsule(shoulder, Vector3(0.77, -0.45, 0.39), 0.045),
      capsule(Vector3(1.05, -0.09, 0.30), Vector3(1.05, -0.09, 0.57), 0.11),
      capsule(Vector3(0.94, -0.21, 0.30), Vector3(0.94, -0.21, 0.57), 0.11),
      capsule(Vector3(1.00, -0.15, 0.89), Vector3(1.00, -0.15, 0.89), 0.106),
      capsule(Vector3(1.16, 0.02, 0.70), Vector3(1.16, 0.02, -0.11), 0.045),
      capsule(shoulder, place + (shoulder - place).normalized() * 0.08, 0.05)};
  person.back().gripper_works_here = true;
  int solves = 0, calls = 0;
  for (auto _ : state) {
    const UprightPlacement p = findUprightPlacement(model, held, place, ready(), shippedConfig(), person.data(),
                                                    static_cast<int>(person.size()));
    solves += p.ik_solves;
    ++calls;
    benchmark::DoNotOptimize(p.q.data());
  }
  state.counters["ik_solves"] = static_cast<double>(solves) / calls;
}
BENCHMARK(BM_UprightPlacementForAReceiver)->Unit(benchmark::kMillisecond);

}  // namespace
