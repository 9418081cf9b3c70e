// The cycle's other jobs run the same HandoverCycle::step with state tables
// of their own (fsm/handover/reach_states.hpp): the paper's reach
// (config/fsm_reach.yaml, fsm_reach_baseline.yaml), `hold`
// (config/fsm_hold.yaml); and a controller config without a collision
// constraint runs the cycle without its collision stage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "config/input_error.hpp"
#include "control/tasks/end_effector_pose_task.hpp"
#include "runtime/handover_cycle.hpp"

namespace handover::runtime {
namespace {

std::string configFile(const char* name) { return std::string(HANDOVER_SOURCE_DIR) + "/config/" + name; }

/// An object `speed` m/s along world x from `start`, sampled every `period`
/// s from `first` on (stamp = arrival, the object measured as its own body).
class ObjectSamples : public perception::PoseSource {
 public:
  ObjectSamples(const Eigen::Isometry3d& start, double first, double period, double speed = 0.0)
      : start_(start), next_(first), period_(period), speed_(speed) {}
  bool poll(double now, perception::PoseSample& out) override {
    if (now + 1e-9 < next_) return false;
    out = perception::PoseSample{};
    out.stamp = now;
    out.has_object = true;
    out.object = perception::Pose::fromIsometry(at(now));
    Eigen::Isometry3d body = Eigen::Isometry3d::Identity();
    body.translation() = at(now).translation() + Eigen::Vector3d(0.0, 0.0, -0.05);
    out.hand = out.forearm = out.upper_arm = perception::Pose::fromIsometry(body);
    next_ += period_;
    ++count_;
    return true;
  }
  Eigen::Isometry3d at(double t) const {
    Eigen::Isometry3d x = start_;
    x.translation().x() += speed_ * t;
    return x;
  }
  int count() const { return count_; }

 private:
  Eigen::Isometry3d start_;
  double next_, period_, speed_;
  int count_ = 0;
};

/// The reach's settings as the paper experiment makes them: its table, the
/// controller config without the collision constraint, an upright object
/// grasped from the side (grasp z along world x).
CycleSettings reachSettings(const char* table) {
  CycleSettings s = defaultCycleSettings();
  auto& c = s.controller.constraints;
  c.erase(std::remove_if(c.begin(), c.end(), [](const control::ElementEntry& e) { return e.type == "collision"; }),
          c.end());
  s.collision_required = false;
  s.fsm_config_path = configFile(table);
  Eigen::Isometry3d grasp = Eigen::Isometry3d::Identity();
  grasp.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  s.object.grasp_in_object = grasp;
  s.object_grasp.placement = grasp;
  return s;
}

Eigen::Isometry3d objectInFront() {
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  x.translation() = Eigen::Vector3d(0.65, 0.1, 0.35);
  return x;
}

TEST(CycleStateTables, ReachStartsWithItsTargetOnTheTcpAndTheObserverOnTheFirstSample) {
  HandoverCycle cycle(reachSettings("fsm_reach.yaml"));
  EXPECT_FALSE(cycle.hasCollision());
  const io::Vector7 q0 = cycle.controller().config().posture.target;
  io::ArmState arm;
  arm.q = q0;
  cycle.start(arm, false);
  ObjectSamples object(objectInFront(), 0.05, 1.0 / 60.0);
  for (int k = 0; k < 50; ++k) {  // no sample yet: the target frame is the TCP, the arm is not pulled
    cycle.step(k * 0.001, arm, object);
    ASSERT_EQ(object.count(), 0);
    EXPECT_LT((cycle.controller().graspFrame().pose.translation() - cycle.controller().tcpPose().translation()).norm(),
              1e-6)
        << "t = " << k * 0.001;
    EXPECT_LT(cycle.controller().lastQdd().norm(), 1e-6);
  }
  EXPECT_TRUE(cycle.adapter().trackingEnabled());
  EXPECT_EQ(cycle.machine().activePath(), "Reach");
  // the pre-grasp frame: the grasp backed off 8 cm along its approach axis
  EXPECT_TRUE(cycle.adapter().trackingOffset().isApprox(
      cycle.machine().context().object.grasp_in_object * Eigen::Translation3d(0.0, 0.0, -0.08), 1e-12));
  EXPECT_GT((cycle.controller().observedState().pose.translation() - objectInFront().translation()).norm(), 0.1);
  // the first sample: the observed frame starts on it, no 0.1 s convergence
  cycle.step(0.05, arm, object);
  ASSERT_EQ(object.count(), 1);
  EXPECT_LT((cycle.controller().observedState().pose.translation() - objectInFront().translation()).norm(), 1e-6);
  EXPECT_EQ(cycle.command().gripper_width, cycle.machine().params().gripper_open_width);
}

TEST(CycleStateTables, BaselineSetPointMovesOnlyWhenANewSampleArrives) {
  HandoverCycle cycle(reachSettings("fsm_reach_baseline.yaml"));
  const control::Controller& ctl = cycle.controller();
  const auto& pose = dynamic_cast<const control::EndEffectorPoseTask&>(ctl.task(ctl.taskIndex("pose")));
  const io::Vector7 q0 = ctl.config().posture.target;
  io::ArmState arm;
  arm.q = q0;
  cycle.start(arm, false);
  ObjectSamples object(objectInFront(), 0.02, 0.01, 0.2);  // moving: every sample is a new set point
  cycle.step(0.0, arm, object);
  EXPECT_FALSE(cycle.adapter().trackingEnabled());
  EXPECT_TRUE(ctl.taskEnabled(ctl.taskIndex("pose")));
  EXPECT_TRUE(pose.target().isApprox(ctl.tcpPose(), 1e-12));  // before any sample: where the TCP is
  int moves = 0, samples = 0;
  Eigen::Isometry3d last = pose.target();
  for (int k = 1; k <= 200; ++k) {
    const int before = object.count();
    cycle.step(k * 0.001, arm, object);
    const bool sampled = object.count() != before;
    const bool moved = !pose.target().isApprox(last, 1e-15);
    EXPECT_EQ(moved, sampled) << "t = " << k * 0.001;
    moves += moved;
    samples += sampled;
    last = pose.target();
  }
  EXPECT_GE(samples, 15);
  EXPECT_EQ(moves, samples);
  // the set point is the pre-grasp pose of the measured object: 8 cm back along the grasp's z (world x)
  const Eigen::Vector3d pre = object.at(0.2).translation() - 0.08 * Eigen::Vector3d::UnitX();
  EXPECT_LT((last.translation() - pre).norm(), 0.01);
}

TEST(CycleStateTables, HoldKeepsTheConfiguredPostureWithTrackingOff) {
  CycleSettings s = defaultCycleSettings();
  s.fsm_config_path = configFile("fsm_hold.yaml");
  HandoverCycle cycle(s);
  const control::Controller& ctl = cycle.controller();
  const io::Vector7 q0 = ctl.config().posture.target;
  io::ArmState arm;
  arm.q = q0;
  cycle.start(arm, false);
  ObjectSamples nobody(objectInFront(), 1e9, 1.0);
  for (int k = 0; k < 20; ++k) cycle.step(k * 0.001, arm, nobody);
  EXPECT_EQ(cycle.machine().activePath(), "Hold");
  EXPECT_FALSE(cycle.adapter().trackingEnabled());
  EXPECT_FALSE(ctl.taskEnabled(ctl.taskIndex("pose")));
  EXPECT_LT(ctl.lastQdd().norm(), 1e-9);  // at the posture, at rest: nothing to do
  // pushed off the posture on joint 1, the posture task pulls it back
  arm.q[0] += 0.1;
  cycle.step(0.02, arm, nobody);
  EXPECT_LT(ctl.lastQdd()[0], -0.5);
}

TEST(CycleStateTables, WithoutACollisionConstraintThePersonReadsFarAway) {
  CycleSettings s = defaultCycleSettings();
  auto& c = s.controller.constraints;
  const std::size_t before = c.size();
  c.erase(std::remove_if(c.begin(), c.end(), [](const control::ElementEntry& e) { return e.type == "collision"; }),
          c.end());
  ASSERT_EQ(c.size() + 1, before);
  // the handover's safety reads the distances: without the constraint the cycle refuses, unless allowed
  try {
    HandoverCycle refused(s);
    ADD_FAILURE() << "a handover cycle without a collision constraint was built";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("collision"), std::string::npos) << e.what();
  }
  s.collision_required = false;
  HandoverCycle cycle(s);
  EXPECT_FALSE(cycle.hasCollision());
  io::ArmState arm;
  arm.q = cycle.controller().config().posture.target;
  cycle.start(arm, false);
  // a person right at the gripper: with the constraint the distances would be centimetres
  Eigen::Isometry3d at_tcp = cycle.controller().tcpPose();
  ObjectSamples person(at_tcp, 0.0, 0.001);
  for (int k = 0; k < 10; ++k) cycle.step(k * 0.001, arm, person);
  EXPECT_TRUE(cycle.fsmInput().hand.valid);
  EXPECT_EQ(cycle.fsmInput().hand_distance, 2.0);
  EXPECT_EQ(cycle.fsmInput().arm_distance, 2.0);
  EXPECT_EQ(cycle.fsmInput().human_distance, 2.0);
  EXPECT_EQ(cycle.controller().fallbackCount(), 0);
}

}  // namespace
}  // namespace handover::runtime
