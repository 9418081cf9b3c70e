// The load estimator (control/wrench/contact_wrench.hpp) on synthetic
// readings: the load share follows the share of the object's weight on the
// sensor, the payload follows the share, an open gripper holds nothing, and
// the feed-forward is what the payload does not explain.
#include <gtest/gtest.h>

#include "control/model/robot_description.hpp"
#include "control/wrench/contact_wrench.hpp"
#include "control/model/rigid_inertia.hpp"

namespace handover::control {
namespace {

constexpr double kDt = 0.001;

struct Fixture {
  Model model = loadModel(defaultRobotDescription(), 0.08);
  Payload object;
  Matrix3 R = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();  // hand pointing down
  Isometry sensor_T_tcp = model.frames[model.frameId("ft_sensor")].placement.inverse() *
                          model.frames[model.frameId("tcp")].placement;
  Fixture() {
    object.mass = 1.0;
    object.com = Vector3(0.0, 0.0, 0.02);
  }
  /// The sensor reading with `share` of the object's weight on it and a
  /// further force `extra` (world) at the sensor.
  Vector6 reading(double share, const Vector3& extra = Vector3::Zero()) const {
    Inertia held;
    held.mass = share * object.mass;
    held.com = object.com;
    Vector6 w = hangingWrench(model.tool, R, model.gravity) +
                hangingWrench(transformInertia(held, sensor_T_tcp), R, model.gravity);
    w.head<3>() += R.transpose() * extra;
    return w;
  }
  /// Mode carry, ramp 0.2 s, started holding the object.
  ContactWrenchEstimator carryingEstimator() const {
    ContactWrenchSettings s;
    s.feed_forward = ContactWrenchSettings::FeedForward::kCarry;
    s.ramp_time = 0.2;
    ContactWrenchEstimator est(model, s, kDt);
    est.start(object, true);
    return est;
  }
  void run(ContactWrenchEstimator& est, const Vector6& reading, bool closed, int cycles, bool at_rest = false,
           bool carried_alone = false) const {
    ContactWrenchInput in;
    in.reading = reading;
    in.sensor_rotation = R;
    in.gripper_closed = closed;
    in.at_rest = at_rest;
    in.carried_alone = carried_alone;
    for (int i = 0; i < cycles; ++i) est.update(in);
  }
};

TEST(ContactWrench, LoadShareFollowsTheWeightOnTheSensor) {
  Fixture f;
  ContactWrenchEstimator est(f.model, ContactWrenchSettings{}, kDt);
  est.start(f.object, false);
  f.run(est, f.reading(0.0), false, 300, true);  // calibrates empty and open
  ASSERT_TRUE(est.calibrated());
  EXPECT_DOUBLE_EQ(est.loadShare(), 0.0);
  for (double share : {0.0, 0.25, 0.6, 1.0}) {
    f.run(est, f.reading(share), true, 200);
    EXPECT_NEAR(est.loadShare(), share, 1e-3) << share;
    EXPECT_NEAR(est.payload().mass, share * f.object.mass, 1e-3) << share;
    EXPECT_NEAR(est.load().z(), -share * f.object.mass * 9.81, 1e-2) << share;
  }
  // more than the object's weight (someone pushes down) is still "all of it"
  f.run(est, f.reading(1.0, Vector3(0, 0, -20.0)), true, 200);
  EXPECT_DOUBLE_EQ(est.loadShare(), 1.0);
  // an open gripper holds nothing, whatever pushes on it
  f.run(est, f.reading(0.5), false, 200);
  EXPECT_DOUBLE_EQ(est.loadShare(), 0.0);
  EXPECT_DOUBLE_EQ(est.payload().mass, 0.0);
}

TEST(ContactWrench, FeedForwardIsWhatThePayloadDoesNotExplain) {
  Fixture f;
  ContactWrenchSettings s;
  s.feed_forward = ContactWrenchSettings::FeedForward::kAlways;
  s.ramp_time = 0.0;
  ContactWrenchEstimator est(f.model, s, kDt);
  est.start(f.object, true);  // starts holding: calibrates with the object
  f.run(est, f.reading(1.0), true, 300, true);
  ASSERT_TRUE(est.calibrated());
  EXPECT_NEAR(est.loadShare(), 1.0, 1e-6);
  EXPECT_LT(est.feedForward().norm(), 1e-6);
  // the receiver pulls 8 N along x and carries half the weight
  f.run(est, f.reading(0.5, Vector3(8.0, 0.0, 0.0)), true, 300);
  EXPECT_NEAR(est.loadShare(), 0.5, 1e-3);
  EXPECT_NEAR(est.feedForward().x(), 8.0, 1e-2);
  EXPECT_LT(est.feedForward().segment<2>(1).norm(), 1e-2);

  // off: estimate only
  ContactWrenchSettings off_settings;
  off_settings.feed_forward = ContactWrenchSettings::FeedForward::kOff;
  ContactWrenchEstimator off(f.model, off_settings, kDt);
  off.start(f.object, true);
  f.run(off, f.reading(1.0), true, 300, true);
  f.run(off, f.reading(0.5, Vector3(8.0, 0.0, 0.0)), true, 300);
  EXPECT_NEAR(off.loadShare(), 0.5, 1e-3);
  EXPECT_EQ(off.feedForward(), Vector6::Zero());
}

TEST(ContactWrench, CarryModeFeedsForwardOnlyWhatTheRobotCarriesAloneAndRamps) {
  Fixture f;
  ContactWrenchEstimator est = f.carryingEstimator();
  f.run(est, f.reading(1.0), true, 300, true);
  ASSERT_TRUE(est.calibrated());
  // the object sits 3 cm off where the model puts it: a torque the payload does not explain
  Fixture shifted = f;
  shifted.object.com = Vector3(0.03, 0.0, 0.02);
  const Vector6 reading = shifted.reading(1.0);
  // a person shares the object: nothing is fed forward
  f.run(est, reading, true, 300, false, false);
  EXPECT_EQ(est.feedForward(), Vector6::Zero());
  // the robot alone: the torque error is fed forward, faded in over ramp_time
  f.run(est, reading, true, 100, false, true);
  const double half_way = est.feedForward().tail<3>().norm();
  f.run(est, reading, true, 200, false, true);
  const double full = est.feedForward().tail<3>().norm();
  EXPECT_NEAR(full, 1.0 * 9.81 * 0.03, 0.02);  // m g x the shift
  EXPECT_NEAR(half_way, 0.5 * full, 0.05 * full);
  // a person takes hold again: faded out
  f.run(est, reading, true, 250, false, false);
  EXPECT_EQ(est.feedForward(), Vector6::Zero());
}

TEST(ContactWrench, DisturbanceFeedbackRampsWithTheCarryWithoutACalibration) {
  // a give: the robot holds the object from the start and moves at once, so
  // the sensor is never calibrated; the wrench is not fed forward, but the
  // joint disturbance feedback (which needs no sensor) follows the carry
  Fixture f;
  ContactWrenchEstimator est = f.carryingEstimator();
  f.run(est, f.reading(1.0), true, 100, false, true);
  ASSERT_FALSE(est.calibrated());
  EXPECT_NEAR(est.disturbanceGain(), 0.5, 1e-9);
  f.run(est, f.reading(1.0), true, 200, false, true);
  EXPECT_EQ(est.disturbanceGain(), 1.0);
  EXPECT_EQ(est.feedForwardGain(), 0.0);
  EXPECT_EQ(est.feedForward(), Vector6::Zero());
  // a person's hand comes to the gripper: it fades out over ramp_time
  f.run(est, f.reading(1.0), true, 100, false, false);
  EXPECT_NEAR(est.disturbanceGain(), 0.5, 1e-9);
  f.run(est, f.reading(1.0), true, 100, false, false);
  EXPECT_EQ(est.disturbanceGain(), 0.0);
}

TEST(ContactWrench, NonFiniteReadingsKeepTheEstimate) {
  Fixture f;
  ContactWrenchEstimator est(f.model, ContactWrenchSettings{}, kDt);
  est.start(f.object, true);
  f.run(est, f.reading(1.0), true, 300, true);
  f.run(est, Vector6::Constant(std::nan("")), true, 10);
  EXPECT_NEAR(est.loadShare(), 1.0, 1e-6);
  EXPECT_TRUE(est.load().allFinite());
}


// A held object braked with the arm pushes on the sensor by its inertia; the
// interaction force (what a person adds) takes that out, so braking into a
// presentation does not read as a pull, while a real pull still does.
TEST(ContactWrench, InteractionForceExcludesTheHeldObjectsInertiaButNotAPull) {
  Fixture f;
  ContactWrenchEstimator est(f.model, ContactWrenchSettings{}, kDt);
  est.start(f.object, true);
  const Vector3 accel(-6.0, 2.0, 1.0);  // m/s^2 of the sensor, world (hard braking)
  const Vector3 g_eff = f.model.gravity - accel;
  Inertia held;
  held.mass = f.object.mass;
  held.com = f.object.com;
  // what the tool and the object put on the sensor at that acceleration
  const Vector6 braking = hangingWrench(f.model.tool, f.R, g_eff) +
                          hangingWrench(transformInertia(held, f.sensor_T_tcp), f.R, g_eff);
  ContactWrenchInput in;
  in.sensor_rotation = f.R;
  in.sensor_acceleration = accel;
  in.gripper_closed = true;
  in.reading = braking;
  for (int i = 0; i < 300; ++i) est.update(in);
  // the load itself carries the 6 N of inertia: a test on it would see a "pull"
  EXPECT_GT((est.load().head<3>() - held.mass * f.model.gravity).norm(), 5.0);
  EXPECT_LT(est.interactionForce().norm(), 1e-6);
  // a person pulling 8 N along +x while the arm brakes
  const Vector3 pull(8.0, 0.0, 0.0);
  in.reading.head<3>() += f.R.transpose() * pull;
  for (int i = 0; i < 300; ++i) est.update(in);
  EXPECT_NEAR((est.interactionForce() - pull).norm(), 0.0, 1e-3);
  // open fingers hold nothing: the interaction is the whole load
  in.gripper_closed = false;
  for (int i = 0; i < 300; ++i) est.update(in);
  EXPECT_NEAR((est.interactionForce() - est.load().head<3>()).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace handover::control
