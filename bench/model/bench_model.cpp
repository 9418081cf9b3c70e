// Cost of the model's per-cycle work (target: BM_ModelUpdate <= 5 us).
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"

namespace {

using namespace handover::control;

const Model& pandaModel() {
  static const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return model;
}

// a few states within the limits, cycled so branch predictors see variety
struct States {
  explicit States(const Model& m) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < kN; ++k)
      for (int i = 0; i < kArmDofs; ++i) {
        q[k][i] = m.q_min[i] + u(rng) * (m.q_max[i] - m.q_min[i]);
        v[k][i] = (2 * u(rng) - 1) * m.v_max[i];
      }
  }
  static constexpr int kN = 16;
  Vector7 q[kN], v[kN];
};

// one control cycle's model update: computeAll + tcp Jacobian + tcp drift
void BM_ModelUpdate(benchmark::State& state) {
  const Model& model = pandaModel();
  Data data(model);
  const States s(model);
  const int tcp = model.frameId("tcp");
  Matrix6x7 J;
  int k = 0;
  for (auto _ : state) {
    computeAll(model, data, s.q[k], s.v[k]);
    frameJacobian(model, data, tcp, J);
    Vector6 drift = frameDrift(model, data, tcp);
    benchmark::DoNotOptimize(J.data());
    benchmark::DoNotOptimize(drift.data());
    benchmark::DoNotOptimize(data.M.data());
    k = (k + 1) % States::kN;
  }
}
BENCHMARK(BM_ModelUpdate);

// the gravity Jacobian the gravity-hold constraint computes in a cycle
// where a joint is near its share of the torque limit
void BM_GravityJacobian(benchmark::State& state) {
  const Model& model = pandaModel();
  const States s(model);
  std::vector<Data> data(States::kN, Data(model));  // each state's kinematics, computed once
  for (int k = 0; k < States::kN; ++k) computeAll(model, data[k], s.q[k], s.v[k]);
  Matrix7 G;
  int k = 0;
  for (auto _ : state) {
    gravityJacobian(model, data[k], G);
    benchmark::DoNotOptimize(G.data());
    k = (k + 1) % States::kN;
  }
}
BENCHMARK(BM_GravityJacobian);

void BM_ForwardKinematics(benchmark::State& state) {
  const Model& model = pandaModel();
  Data data(model);
  const States s(model);
  int k = 0;
  for (auto _ : state) {
    forwardKinematics(model, data, s.q[k], s.v[k]);
    benchmark::DoNotOptimize(data.oMb[7].data());
    k = (k + 1) % States::kN;
  }
}
BENCHMARK(BM_ForwardKinematics);

void BM_Crba(benchmark::State& state) {
  const Model& model = pandaModel();
  Data data(model);
  const States s(model);
  forwardKinematics(model, data, s.q[0], s.v[0]);
  for (auto _ : state) {
    crba(model, data);
    benchmark::DoNotOptimize(data.M.data());
  }
}
BENCHMARK(BM_Crba);

void BM_Rnea(benchmark::State& state) {
  const Model& model = pandaModel();
  Data data(model);
  const States s(model);
  forwardKinematics(model, data, s.q[0], s.v[0]);
  const Vector7 a = s.v[1];
  for (auto _ : state) {
    Vector7 tau = rnea(model, data, a);
    benchmark::DoNotOptimize(tau.data());
  }
}
BENCHMARK(BM_Rnea);

}  // namespace
