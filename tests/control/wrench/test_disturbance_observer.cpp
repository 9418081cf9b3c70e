// The joint disturbance observer (control/wrench/disturbance_observer.hpp) on
// a rigid-body plant integrated with our own model: it recovers a constant
// torque the model does not know, clips it, and, fed back by the Controller,
// lets a posture move reach its goal although the model misplaces the held
// object's mass (which leaves the acceleration-level PD short of it).
#include <gtest/gtest.h>

#include <cmath>

#include "control/controller.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/robot_description.hpp"
#include "control/wrench/disturbance_observer.hpp"

namespace handover::control {
namespace {

constexpr double kObserverDt = 0.001;

const Model& panda() {
  static const Model m = loadModel(defaultRobotDescription(), 0.08);
  return m;
}

/// Rigid-body plant: M qdd = tau + d - h, semi-implicit Euler (the simulator's).
struct Plant {
  Data data{panda()};
  Vector7 q, v = Vector7::Zero();
  Vector7 disturbance = Vector7::Zero();
  explicit Plant(const Vector7& q0) : q(q0) {}
  void step(const Vector7& tau) {
    computeAll(panda(), data, q, v);
    const Vector7 qdd = data.M.ldlt().solve(tau + disturbance - data.h);
    v += qdd * kObserverDt;
    q += v * kObserverDt;
  }
};

/// Drives the plant with gravity compensation that does not know its
/// disturbance, `steps` periods, the observer watching (learning or not).
void observeUnderGravityCompensation(Plant& plant, DisturbanceObserver& obs, int steps, bool learn = true) {
  Data model_data(panda());
  Vector7 tau = Vector7::Zero();
  for (int k = 0; k < steps; ++k) {
    computeAll(panda(), model_data, plant.q, plant.v);
    obs.update(model_data, plant.v, tau, learn);
    tau = model_data.h;
    plant.step(tau);
  }
}

const Vector7 kReady = (Vector7() << 0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398).finished();

/// The ready arm with a torque on every joint that the model does not know.
Plant disturbedPlant() {
  Plant plant(kReady);
  plant.disturbance << 0.0, 0.5, 0.0, -0.3, 0.05, -0.2, 0.08;
  return plant;
}

/// An observer that may hold up to the whole torque limits.
DisturbanceObserver unclippedObserver() {
  DisturbanceSettings s;
  s.max_torque_fraction = 1.0;
  return DisturbanceObserver(s, panda().tau_max, kObserverDt);
}

TEST(DisturbanceObserver, RecoversATorqueTheModelDoesNotKnow) {
  Plant plant = disturbedPlant();
  DisturbanceObserver obs = unclippedObserver();
  observeUnderGravityCompensation(plant, obs, 300);
  // within 1 % of its size: the observer evaluates M and h at the period's
  // end, the plant moved under them (the arm falls freely along d)
  const double tol = 0.01 * plant.disturbance.norm();
  for (int i = 0; i < 7; ++i) EXPECT_NEAR(obs.torque()[i], plant.disturbance[i], tol) << "joint " << i + 1;
  obs.reset();
  EXPECT_TRUE(obs.torque().isZero());
}

TEST(DisturbanceObserver, HoldsItsEstimateWhileNotLearning) {
  // a person may be touching: what the observer then sees is their push,
  // so the estimate stays what it was
  Plant plant = disturbedPlant();
  DisturbanceObserver obs = unclippedObserver();
  observeUnderGravityCompensation(plant, obs, 300);
  const Vector7 learnt = obs.torque();
  plant.disturbance *= 3.0;
  observeUnderGravityCompensation(plant, obs, 100, false);
  EXPECT_EQ(obs.torque(), learnt);
  // learning again, it moves to the new disturbance
  observeUnderGravityCompensation(plant, obs, 300);
  EXPECT_GT((obs.torque() - learnt).norm(), 0.5 * (2.0 * learnt).norm());
}

TEST(DisturbanceObserver, HoldsAtMostItsShareOfTheTorqueLimits) {
  Plant plant(kReady);
  plant.disturbance << 30.0, 0.0, 0.0, 0.0, 0.0, 0.0, -5.0;
  DisturbanceSettings s;
  s.max_torque_fraction = 0.1;
  DisturbanceObserver obs(s, panda().tau_max, kObserverDt);
  observeUnderGravityCompensation(plant, obs, 200);
  EXPECT_NEAR(obs.torque()[0], 0.1 * panda().tau_max[0], 1e-9);
  EXPECT_NEAR(obs.torque()[6], -0.1 * panda().tau_max[6], 1e-9);
}

/// A posture move while carrying: the controller's payload sits 2 cm from
/// where the plant's does. Returns joint 7's distance to the goal after 6 s.
double carryError(double gain, bool compensation = true) {
  const Vector7 goal = (Vector7() << 0.0, -0.3, -0.3, -2.29, 1.61, 1.75, 1.82).finished();
  Payload truth;
  truth.mass = 0.8;
  truth.com = Vector3(0.09, 0.02, 0.0);
  Payload believed = truth;
  believed.com = Vector3(0.09, 0.0, 0.0);
  Plant plant(kReady);
  setPayload(panda(), plant.data, truth);
  ControllerConfig cfg = loadControllerConfig(defaultControllerConfigPath());
  if (!compensation) cfg.disturbance.compensation = DisturbanceSettings::Compensation::kOff;
  Controller ctl(panda(), cfg);
  ControlInputs in;
  in.q = plant.q;
  ctl.reset(in);
  ctl.setTaskEnabled("tracking", false);
  ctl.setPayload(believed);
  ctl.setPostureTarget(goal);
  ctl.setDisturbanceFeedback(gain, true);
  for (int k = 0; k < 6000; ++k) {
    in.time = k * kObserverDt;
    in.q = plant.q;
    in.qd = plant.v;
    plant.step(ctl.step(in));
  }
  EXPECT_EQ(ctl.fallbackCount(), 0);
  return (plant.q - goal).cwiseAbs().maxCoeff();
}

TEST(DisturbanceObserver, FedBackAPostureMoveReachesItsGoalDespiteAMisplacedPayload) {
  const double without = carryError(0.0);
  const double with = carryError(1.0);
  EXPECT_GT(without, 0.1);  // the weak wrist spring stops short
  EXPECT_LT(with, 0.01);
  EXPECT_NEAR(carryError(1.0, false), without, 1e-9);  // compensation off: the gain is ignored
}

}  // namespace
}  // namespace handover::control
