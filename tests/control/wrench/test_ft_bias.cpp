// Bias calibration of the wrist F/T sensor (control/wrench/ft_bias.hpp):
// calibrated at one wrist orientation with the gripper empty, it must leave
// no load at another orientation, in the simulator (MuJoCo's sensor against
// our model's tool: Model::tool from the URDF) and with a synthetic offset.
#include <gtest/gtest.h>

#include "control/model/algorithms.hpp"
#include "control/model/robot_description.hpp"
#include "control/wrench/ft_bias.hpp"
#include "tests/scenes/sim/sim_test_support.hpp"

namespace handover::control {
namespace {

struct Sample {
  Vector6 reading;
  Matrix3 R;  // sensor axes in the world, from our kinematics
};

/// Holds `q` in the simulator for 0.5 s (gripper open) and reads the sensor.
Sample holdAndRead(sim::Simulation& sim, const Model& model, const Vector7& q) {
  sim.reset(q, 0.08);
  for (int i = 0; i < 500; ++i) sim::test::holdStep(sim, q);
  const io::ArmState s = sim.armState();
  Data data(model);
  forwardKinematics(model, data, s.q, s.qd);
  return {s.wrench, framePlacement(model, data, model.frameId("ft_sensor")).linear()};
}

Vector7 turnedWrist() {
  Vector7 q = sim::test::readyPosture();
  q[4] += 0.6;   // the forearm turns the hand sideways
  q[5] -= 0.7;   // the wrist tilts
  q[6] += 1.2;   // the flange turns
  return q;
}

TEST(FtBias, CalibratedEmptyAtOnePoseReadsNoLoadAtAnother) {
  const Model model = loadModel(defaultRobotDescription(), 0.08);
  ASSERT_GT(model.tool.mass, 0.5);  // the hand and fingers hang below the sensor
  sim::Simulation sim;
  sim.load();
  EXPECT_NEAR(model.tool.mass, sim.handMass(), 0.01);

  const Sample a = holdAndRead(sim, model, sim::test::readyPosture());
  const Sample b = holdAndRead(sim, model, turnedWrist());
  ASSERT_GT((a.R.transpose() * b.R - Matrix3::Identity()).norm(), 0.5);  // really another orientation

  FtBiasCalibrator cal(50);
  for (int i = 0; i < 50; ++i) cal.add(a.reading, a.R, model.tool, model.gravity);
  ASSERT_TRUE(cal.done());
  const Vector6 rest_a = cal.compensate(a.reading, a.R, model.tool, model.gravity);
  const Vector6 rest_b = cal.compensate(b.reading, b.R, model.tool, model.gravity);
  EXPECT_LT(rest_a.head<3>().norm(), 1e-9);
  EXPECT_LT(rest_b.head<3>().norm(), 0.15) << rest_b.transpose();  // N, of a 7.5 N hand
  EXPECT_LT(rest_b.tail<3>().norm(), 0.02) << rest_b.transpose();  // N m

  // a constant bias (the reading at a, subtracted as is) would not do: the weight turned
  const Vector6 naive = b.reading - a.reading;
  EXPECT_GT(naive.head<3>().norm(), 1.0) << naive.transpose();
}

TEST(FtBias, RecoversASensorOffsetWhateverTheOrientation) {
  const Model model = loadModel(defaultRobotDescription(), 0.08);
  Vector6 offset;
  offset << 1.5, -0.7, 2.0, 0.05, -0.02, 0.03;
  const Matrix3 Ra = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();
  const Matrix3 Rb = (Eigen::AngleAxisd(0.8, Vector3::UnitY()) * Eigen::AngleAxisd(2.0, Vector3::UnitZ())).toRotationMatrix();
  FtBiasCalibrator cal(10);
  EXPECT_FALSE(cal.done());
  for (int i = 0; i < 10; ++i) cal.add(offset + hangingWrench(model.tool, Ra, model.gravity), Ra, model.tool, model.gravity);
  ASSERT_TRUE(cal.done());
  EXPECT_LT((cal.offset() - offset).norm(), 1e-12);
  const Vector6 at_b = offset + hangingWrench(model.tool, Rb, model.gravity);
  EXPECT_LT(cal.compensate(at_b, Rb, model.tool, model.gravity).norm(), 1e-12);
  // non-finite readings are not samples
  cal.restart();
  Vector6 bad = Vector6::Constant(std::nan(""));
  cal.add(bad, Ra, model.tool, model.gravity);
  EXPECT_EQ(cal.count(), 0);
}

}  // namespace
}  // namespace handover::control
