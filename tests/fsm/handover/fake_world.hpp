// Synthetic inputs for the handover machine: a recording fake controller and
// a kinematic toy world (no physics) in which the TCP moves toward what the
// controller was last told, the gripper closes on the object when it is
// between the fingers, the wrist force shows the object's weight when the
// robot alone carries it, and the person's hand is scripted by the test.
#pragma once

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "fsm/handover/handover_fsm.hpp"

namespace handover::fsm::test {

/// Where the person's hand meets the robot (offer) and where it goes when they leave.
inline const Vector3 kMeet(0.55, 0.0, 0.30);
inline const Vector3 kAway(1.0, -0.3, 0.2);

struct RecordingController : ControllerInterface {
  bool record = true;  ///< false: keep the state only (no allocation)
  std::vector<std::string> calls;
  ObservationTarget observation = ObservationTarget::kNone;
  bool tracking = false;
  Isometry offset = Isometry::Identity();
  bool offset_planned = false;
  double offset_speed = 0.0, offset_acceleration = 0.0;  // the offset's slide fed forward (m/s, m/s^2)
  bool pose_active = false;
  Isometry pose = Isometry::Identity();
  Vector6 pose_velocity = Vector6::Zero();  // the set-point's motion fed forward
  bool posture_active = false;
  Vector7 posture = Vector7::Zero();
  Vector7 posture_velocity = Vector7::Zero();  // the reference's motion fed forward
  double speed = 1.0;
  bool gains_active = false;     // values only (not in `calls`)
  double gains_translation = 0.0, gains_orientation = 0.0;  // 1/s^2, when gains_active
  double gains_max_speed = 0.0;  // m/s, the phase's own speed limit (0: the task's)
  bool pose_gains_active = false;  // the pose task's, values only
  double pose_gains_translation = 0.0;
  bool hand_relaxed = false;     // values only (not in `calls`)
  bool fingers_around_object = false;      // values only (not in `calls`)
  bool anticipate = false;
  double gripper_width = 0.08;
  bool payload = false;

  static std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.2f", v);
    return b;
  }
  void setObservationTarget(ObservationTarget t) override {
    observation = t;
    if (record) calls.push_back(std::string("observe ") + toString(t));
  }
  // task handles: 0 tracking, 1 pose, 2 posture, 3.. `extra_tasks`
  std::vector<std::string> extra_tasks;
  std::vector<int> extra_enabled;  ///< per extra task: -1 as configured, 0 off, 1 on
  int taskHandle(const std::string& name) const override {
    if (name == "tracking") return 0;
    if (name == "pose") return 1;
    if (name == "posture") return 2;
    for (std::size_t i = 0; i < extra_tasks.size(); ++i)
      if (extra_tasks[i] == name) return 3 + static_cast<int>(i);
    return -1;
  }
  void setTaskEnabled(int task, bool on) override {
    if (task == 0) {
      tracking = on;
      if (record) calls.push_back(on ? "tracking on" : "tracking off");
    } else if (task == 1) {
      if (!on) pose_active = false;
      if (record && !on) calls.push_back("clear pose");
    } else if (task >= 3 && task - 3 < static_cast<int>(extra_tasks.size())) {
      extra_enabled.resize(extra_tasks.size(), -1);
      extra_enabled[task - 3] = on ? 1 : 0;
    }
  }
  void resetTaskEnabled(int task) override {
    if (task >= 3 && task - 3 < static_cast<int>(extra_tasks.size())) {
      extra_enabled.resize(extra_tasks.size(), -1);
      extra_enabled[task - 3] = -1;
    }
  }
  void setTaskTarget(int task, const TaskTarget& t) override {
    if (task == 1 && t.kind == TaskTarget::Kind::kPose) {
      pose_active = true;
      pose = t.pose;
      pose_velocity = t.velocity;
      if (record) calls.push_back("pose");
    } else if (task == 2) {
      posture_active = t.kind == TaskTarget::Kind::kJoints;
      if (posture_active) posture = t.q;
      posture_velocity = posture_active ? t.qd : Vector7::Zero();
      if (record) calls.push_back(posture_active ? "posture" : "clear posture");
    }
  }
  void setTaskGains(int task, const TaskGains& g) override {
    if (task == 1) {
      pose_gains_active = g.active;
      pose_gains_translation = g.translation;
      return;
    }
    if (task != 0) return;
    gains_active = g.active;
    gains_translation = g.translation;
    gains_orientation = g.orientation;
    gains_max_speed = g.max_speed;
  }
  void setTaskOffset(int task, const TrackingOffset& o) override {
    if (task != 0) return;
    offset = o.target_in_observed;
    offset_planned = o.planned;
    offset_speed = o.approach_speed;
    offset_acceleration = o.approach_acceleration;
    if (record) calls.push_back("offset");
  }
  void setSpeedScale(double s) override {
    speed = s;
    if (record) calls.push_back("speed " + num(s));
  }
  void relaxHandClearance(bool relaxed) override { hand_relaxed = relaxed; }
  void fingersAroundObject(bool around) override { fingers_around_object = around; }
  void anticipateRest(bool on) override { anticipate = on; }
  void setGripper(double w, double) override {
    gripper_width = w;
    if (record) calls.push_back("gripper " + num(w));
  }
  void setPayload(double m, const Vector3&) override {
    payload = true;
    if (record) calls.push_back("payload " + num(m));
  }
  void clearPayload() override {
    payload = false;
    if (record) calls.push_back("clear payload");
  }
  int count(const std::string& call) const {
    int n = 0;
    for (const auto& c : calls) n += c == call;
    return n;
  }
};

struct World {
  static constexpr double kDt = 0.001;
  static constexpr double kPersonIDist = 0.08;  // collision.yaml person pairs: iDist 0.05 + margin 0.03
  static constexpr double kHandMass = 0.73;  // kg, the gripper hanging on the sensor
  double time = 0.0;
  Isometry tcp = Isometry::Identity();
  Vector3 tcp_vel = Vector3::Zero();
  Vector3 hand = Vector3(0.9, 0.2, 0.2);      // person's grip point
  Vector3 hand_goal = hand;
  double hand_speed = 0.5;                    // m/s along a straight line
  Vector3 hand_vel = Vector3::Zero();
  Vector3 object_in_hand = Vector3(0, 0, 0.05);
  bool person_holds = true;
  bool robot_grip = false;
  bool graspable = true;     // false: fingers close on nothing
  double width = 0.08;
  double object_width = 0.04;
  double grip_reach = 0.015;  // m: the fingers stop on the object with the TCP this near its centre
  Vector3 object = Vector3::Zero();
  double mass = 0.3;
  Vector3 pull = Vector3::Zero();   // force of a pulling person, while both hold
  Vector3 brush = Vector3::Zero();  // force of a hand that pushes the carried object without holding it
  Vector3 inertia = Vector3::Zero();  // the held object's inertial force as the arm brakes: raw wrist force only
  double human_distance = 1.0;  // robot to the person's hand
  double arm_distance = 1.0;    // robot to the person's forearm / upper arm
  bool dropout = false;     // perception sends nothing
  double velocity_noise = 0.0;  // m/s: the perceived velocity of the person's hand and what it holds jitters by
                                // this much, turning each ms (a filter's estimate from a noisy sensor)
  double speed_std = 0.0;       // m/s: what perception reports as that estimate's standard deviation
  double position_noise = 0.0;  // m: the perceived position of the person's hand wanders by this much, a
                                // new direction every 1/30 s (a 30 Hz tracker's filtered samples)
  bool knows_rest = false;  // perception predicts where the hand's move ends (its goal)
  double last_sample = 0.0;
  bool hand_open = true;
  bool arm_stuck = false;   // the arm cannot move (a joint at its limit, a person in the way)
  double joint_limit_margin = 1e9;  // rad, the arm's nearest joint to its position limit
  double share = -1.0;      // >= 0: the load share the estimator reports while the fingers hold (a weight coming over)
  Vector6 tool_contact = Vector6::Zero();  // what touches the gripper: [force; torque about the TCP], world
  bool payload_seen = false;      // the controller carried a payload at the last step
  bool released_in_hand = false;  // the payload was cleared since: perception keeps the object in the hand
  Vector3 object_left_in_hand = Vector3::Zero();  // where the fingers left it, from the hand
  TrackingPlan object_plan;  // what a grasp planner would report (invalid: none)
  TrackingPlan hand_plan;

  World() {
    tcp.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
    tcp.translation() = Vector3(0.31, 0.0, 0.49);
    object = hand + object_in_hand;
  }

  void moveHand(const Vector3& goal, double speed) {
    hand_goal = goal;
    hand_speed = speed;
  }

  Isometry objectPose() const {
    Isometry T = Isometry::Identity();
    T.translation() = object;
    return T;
  }
  Isometry handPose() const {
    Isometry T = Isometry::Identity();
    T.translation() = hand;
    return T;
  }

  /// What the controller would make the TCP aim at.
  Isometry desired(const RecordingController& c) const {
    if (c.tracking && c.observation != ObservationTarget::kNone) {
      return (c.observation == ObservationTarget::kObject ? objectPose() : handPose()) * c.offset;
    }
    if (c.pose_active) return c.pose;
    return tcp;
  }

  void advance(const RecordingController& c) {
    time += kDt;
    if (payload_seen && !c.payload) {
      released_in_hand = true;
      object_left_in_hand = tcp.translation() - hand;
    }
    if (c.payload) released_in_hand = false;
    payload_seen = c.payload;
    // the person's hand: straight line at constant speed
    const Vector3 dh = hand_goal - hand;
    const double step = std::min(dh.norm(), hand_speed * kDt);
    hand_vel = dh.norm() > 1e-12 ? Vector3(dh.normalized() * step / kDt) : Vector3::Zero();
    hand += hand_vel * kDt;
    // the TCP: first order toward the desired pose, speed-scaled and capped;
    // a moving pose set-point's velocity fed forward, as the pose task does
    const Isometry d = desired(c);
    const Vector3 err = d.translation() - tcp.translation();
    const bool fed = c.pose_active && !(c.tracking && c.observation != ObservationTarget::kNone);
    Vector3 v = (5.0 * err + (fed ? Vector3(c.pose_velocity.head<3>()) : Vector3::Zero())) * c.speed;
    if (v.norm() > 0.5) v = v.normalized() * 0.5;
    if (arm_stuck) v.setZero();
    tcp_vel = v;
    tcp.translation() += v * kDt;
    tcp.linear() = d.linear();
    // gripper fingers at 0.1 m/s, stopped by the object if it is between them
    const bool between = graspable && (object - tcp.translation()).norm() < grip_reach;
    const double target = c.gripper_width;
    const double dw = std::max(-0.1 * kDt, std::min(0.1 * kDt, target - width));
    width += dw;
    if (between && width <= object_width) {
      width = object_width;
      robot_grip = true;
    }
    if (width > object_width + 0.005) robot_grip = false;
    // the object goes with whoever holds it
    if (person_holds) object = hand + object_in_hand;
    else if (robot_grip) object = tcp.translation();
    else object.z() = std::max(-0.5, object.z() - 0.5 * kDt);  // falls (not expected here)
    if (!dropout) last_sample = time;
  }

  HandoverInput input(const RecordingController& c) const {
    HandoverInput in;
    in.time = time;
    in.tcp_pose = tcp;
    in.tcp_velocity.head<3>() = tcp_vel;
    in.joint_limit_margin = joint_limit_margin;
    in.finger_width = width;
    const bool robot_carries = robot_grip && !person_holds;
    Vector3 f(0, 0, -(kHandMass + (robot_carries ? mass : 0.0)) * 9.81);
    if (robot_grip && person_holds) f += pull;
    if (robot_grip) f += brush;
    if (robot_grip) f += inertia;  // the estimator's interaction force takes it out again
    in.wrench.head<3>() = f;
    in.load_share = robot_carries ? 1.0 : 0.0;  // what control::ContactWrenchEstimator would report
    if (robot_grip && share >= 0.0) in.load_share = share;
    // beyond the tool and the whole object (the estimator's interaction force): the
    // person's support while they carry it, their pull while both hold it
    if (robot_grip)
      in.interaction_force =
          Vector3(0, 0, robot_carries ? 0.0 : mass * 9.81) + (person_holds ? pull : Vector3::Zero()) + brush;
    else
      in.interaction_force = tool_contact.head<3>();  // holding nothing: what touches the gripper
    const double age = time - last_sample;
    in.hand.pose = handPose();
    const double sample_turn = 2.4 * std::floor(time * 30.0);  // rad: a new direction every sample
    in.hand.pose.translation() += position_noise * Vector3(std::cos(sample_turn), 0.0, std::sin(sample_turn));
    const double turn = 2.0 * time * 1000.0;  // rad: a new direction every ms
    const Vector3 jitter = velocity_noise * Vector3(std::cos(turn), std::sin(turn), 0.0);
    in.hand.velocity.head<3>() = hand_vel + jitter;
    in.hand.speed_std = in.object.speed_std = speed_std;
    in.hand.valid = !dropout;
    in.hand.age = age;
    // as the runtime's estimator: while the robot carries a payload the object is where the
    // gripper holds it (ObjectHolder::Robot), whoever else holds it too; let go, it stays in
    // the person's hand where the fingers left it (HandoverCycle::step)
    in.object.pose = objectPose();
    if (c.payload) in.object.pose.translation() = tcp.translation();
    else if (released_in_hand) in.object.pose.translation() = hand + object_left_in_hand;
    in.object.velocity.head<3>() = person_holds && !c.payload ? Vector3(hand_vel + jitter) : tcp_vel;
    in.object.valid = !dropout;
    in.object.age = age;
    if (knows_rest) {  // a perfect reach prediction: where the hand's move ends
      in.hand.rest_known = in.object.rest_known = true;
      in.hand.rest_pose = in.hand.pose;
      in.hand.rest_pose.translation() = hand_goal;
      in.object.rest_pose = in.object.pose;
      if (person_holds) in.object.rest_pose.translation() += hand_goal - hand;
    }
    in.tool_contact = tool_contact;  // and the weight the robot carries (the estimator's load)
    if (robot_carries) in.tool_contact.z() -= mass * 9.81;
    in.hand_open = hand_open;
    in.hand_distance = human_distance;
    in.arm_distance = arm_distance;
    in.human_distance = std::min(human_distance, arm_distance);
    in.person_constraint_engaged = in.human_distance < kPersonIDist;
    in.observed_target = c.observation;
    in.observed_pose = c.observation == ObservationTarget::kHand ? handPose() : objectPose();
    in.target_pose = desired(c);
    in.target_velocity.head<3>() =
        c.observation == ObservationTarget::kHand ? Vector3(hand_vel + jitter) : in.object.velocity.head<3>().eval();
    in.holds_object = robot_carries;
    in.object_plan = object_plan;
    in.hand_plan = hand_plan;
    return in;
  }
};

/// The machine on the shipped config, the fake controller and the world.
struct Rig {
  RecordingController ctl;
  World world;
  std::unique_ptr<HandoverFsm> fsm;
  /// The scripted person, called every step before the machine (may be empty).
  std::function<void(World&)> person;
  /// step() runs the planning stage (HandoverFsm::plan) before the machine,
  /// as runtime::HandoverCycle does; false: the test answers when it wants.
  bool plan_stage = true;
  /// anticipate_reach: the shipped table with params.tracking.anticipate_reach on.
  /// shape: the object's (unknown: the gripper slides straight in).
  /// edit: changes to the shipped table before it is loaded.
  explicit Rig(bool robot_starts_with_object = false, bool anticipate_reach = false,
               const io::ObjectShape& shape = io::ObjectShape{},
               const std::function<void(YAML::Node&)>& edit = nullptr) {
    ObjectInfo obj;
    obj.mass = world.mass;
    obj.shape = shape;
    if (anticipate_reach || edit) {
      YAML::Node doc = YAML::LoadFile(HandoverFsm::defaultConfigPath());
      if (anticipate_reach) doc["params"]["tracking"]["anticipate_reach"] = true;
      if (edit) edit(doc);
      fsm = std::make_unique<HandoverFsm>(YamlReader(doc, HandoverFsm::defaultConfigPath(), ""), ctl, obj);
    } else {
      fsm = HandoverFsm::fromFile(HandoverFsm::defaultConfigPath(), ctl, obj);
    }
    if (robot_starts_with_object) {
      world.person_holds = false;
      world.robot_grip = true;
      world.width = world.object_width;
      ctl.gripper_width = 0.0;
      world.object = world.tcp.translation();
      world.hand = world.hand_goal = Vector3(1.0, 0.3, 0.1);
    }
  }
  void step() {
    if (person) person(world);
    if (plan_stage) fsm->plan();
    fsm->step(world.input(ctl));
    world.advance(ctl);
  }
  /// Steps until `pred` holds or `seconds` pass; returns whether it held.
  template <class Pred>
  bool runUntil(Pred pred, double seconds) {
    const double end = world.time + seconds;
    while (world.time < end) {
      step();
      if (pred()) return true;
    }
    return false;
  }
  bool runUntilState(const std::string& leaf, double seconds) {
    return runUntil([&] { return endsWith(fsm->activePath(), leaf); }, seconds);
  }
  void runFor(double seconds) {
    runUntil([] { return false; }, seconds);
  }
  static bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
  }
  /// Visited states without the meta states (a meta entry is followed by its child).
  std::vector<std::string> leaves() const {
    const auto all = fsm->visitedStates();
    std::vector<std::string> out;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (i + 1 < all.size() && all[i + 1].rfind(all[i] + "/", 0) == 0) continue;
      out.push_back(all[i].substr(all[i].rfind('/') + 1));
    }
    return out;
  }
  /// Index of the first call equal to `call` at or after `from` (-1 if none).
  int findCall(const std::string& call, int from = 0) const {
    for (int i = from; i < static_cast<int>(ctl.calls.size()); ++i) {
      if (ctl.calls[static_cast<std::size_t>(i)] == call) return i;
    }
    return -1;
  }
};

using Leaves = std::vector<std::string>;

}  // namespace handover::fsm::test
