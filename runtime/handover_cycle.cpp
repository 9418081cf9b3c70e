#include "runtime/handover_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "control/model/algorithms.hpp"
#include "fsm/handover/handover_params.hpp"
#include "perception/perception_config.hpp"
#include "runtime/collision_queries.hpp"
#include "config/config_directory.hpp"

namespace handover::runtime {

namespace {

constexpr double kFloorZ = -0.75;  // m, the floor under the person (design notes 1)
double clip(double v) { return std::isfinite(v) ? std::min(v, 2.0) : 2.0; }

// the trunk is not tracked: it stands under the tracked shoulder, facing the
// declared way, on the floor (the torso frame of io::HumanBodyPoses)
control::Isometry torsoUnderShoulder(const control::Vector3& shoulder, const CycleSettings::PersonStand& stand) {
  const control::Vector3 right(std::sin(stand.yaw), -std::cos(stand.yaw), 0.0);
  control::Vector3 base = shoulder - stand.shoulder_side * right;
  base.z() = kFloorZ;
  control::Isometry torso = control::Isometry::Identity();
  torso.linear() = Eigen::AngleAxisd(stand.yaw, control::Vector3::UnitZ()).toRotationMatrix();
  torso.translation() = base;
  return torso;
}
}  // namespace

CycleSettings defaultCycleSettings() {
  CycleSettings s;
  s.robot = control::defaultRobotDescription();
  s.controller = control::loadControllerConfig(control::defaultControllerConfigPath());
  s.collision = control::loadCollisionConfig(control::defaultCollisionConfigPath());
  s.fsm_config_path = fsm::HandoverFsm::defaultConfigPath();
  // the gripper's range and force: the state machine's parameters (one place)
  const fsm::HandoverParams fp = fsm::loadHandoverParams(YamlReader::loadFile(s.fsm_config_path).child("params"));
  s.gripper_open_width = fp.gripper_open_width;
  s.gripper_force = fp.gripper_force;
  s.ft_gravity_sign = fp.ft_gravity_sign;
  const perception::PerceptionConfig p = perception::loadPerceptionConfig(perception::defaultPerceptionConfigPath());
  s.estimator = p.estimator;  // staleness, motion model, prediction, gates
  s.target.blend_time = p.blend_time;
  s.reach_prediction = p.reach;
  s.grasp_selection = control::grasp::loadGraspSelectionConfig(configFile("grasp_selection.yaml"));
  return s;
}

HandoverCycle::HandoverCycle(const CycleSettings& settings)
    : settings_(settings),
      controller_(control::loadModel(settings.robot, control::Model{}.finger_opening), settings.controller,
                  settings.registry, &settings.collision),
      estimator_(settings.estimator),
      obs_target_(settings.target),
      reach_(settings.reach_prediction),
      adapter_(controller_, obs_target_, settings.object_grasp, settings.gripper_open_width),
      contact_(controller_.model(), settings.controller.contact_wrench, settings.controller.period) {
  // the collision constraint the cycle feeds (stage 6) and queries; where
  // allowed (the paper's reach, a negative control), a controller config
  // without one runs without stage 6, and the state machine reads no person nearby
  for (const auto& c : controller_.constraints()) {
    if (!collision_) collision_ = std::dynamic_pointer_cast<control::CollisionConstraint>(c);
  }
  if (!collision_ && settings.collision_required) {
    // the handover's safety (slow down, stop) reads the robot-person distances
    throw InputError(settings.controller.constraints.empty() || settings.controller.constraints.front().file.empty()
                         ? std::string("controller config: key 'constraints': the handover cycle needs a constraint of "
                                       "type collision")
                         : settings.controller.constraints.front().file +
                               ": key 'constraints': the handover cycle needs a constraint of type collision");
  }
  if (collision_) {
    hand_rule_ = collision_->collisionModel().ruleIndex("person_hand_gripper");
    adapter_.setCollision(collision_.get(), collision_->collisionModel().ruleIndex("object_gripper"));
  }
  ft_frame_ = controller_.model().frameId("ft_sensor");
  machine_ = settings.fsm_config
                 ? std::make_unique<fsm::HandoverFsm>(YamlReader(*settings.fsm_config, settings.fsm_config_path, ""),
                                                      adapter_, settings.object)
                 : fsm::HandoverFsm::fromFile(settings.fsm_config_path, adapter_, settings.object);
  predict_reach_ = machine_->params().anticipate_reach;  // nobody reads the prediction otherwise
  if (collision_) {
    const control::CollisionModel& cm = collision_->collisionModel();
    for (const control::CollisionPair& p : cm.pairs) forecast_hand_ |= p.other_body == cm.human_hand_forecast;
  }
  if (!settings.object_grasps.empty()) {
    GraspPlanningSettings ps;
    ps.config = settings.grasp_selection;
    ps.object_grasps = settings.object_grasps;
    ps.presentation = machine_->context().presentation.offset;
    ps.presentation_pivot = machine_->params().object_in_hand.translation();
    ps.held_grasp = machine_->context().grasp.offset;
    ps.object_shape = machine_->context().object.shape;
    ps.forearm_length = settings.forearm_length;
    ps.upper_arm_length = settings.upper_arm_length;
    ps.forearm_radius = settings.collision.person.forearm_radius;
    ps.upper_arm_radius = settings.collision.person.upper_arm_radius;
    ps.hand_radius = 0.5 * settings.collision.person.hand_size.maxCoeff();
    ps.hand_box = settings.collision.person.hand_offset;
    ps.hand_box_half_extents = 0.5 * settings.collision.person.hand_size;
    if (settings.stand.declared)
      ps.trunk = trunkObstacles(settings.collision.person.trunk, settings.collision.person.free_arm_radius);
    if (collision_) ps.keeps = personKeeps(collision_->collisionModel());
    planning_ = std::make_unique<GraspPlanning>(controller_.model(), ps);
    machine_->setPlanner(planning_.get());
  }
}

void HandoverCycle::plan() {
  // the reach's end from the last step's hand estimate (a fit per new sample: not in the 1 ms step)
  const perception::HumanEstimate& h = estimate_->human;
  if ((predict_reach_ || forecast_hand_) && h.valid && !h.stale)
    reach_.add(estimate_->time, h.hand, hand_vel_.velocity().head<3>().norm());
  if (!planning_) return;
  // once the reach's end is known the arm heads for one grasp there: no switching on the
  // way, nor once the hand rests there. A reach whose end was never trusted (lost in a
  // dropout, wandering) holds nothing: the first choice was made on a moving hand
  planning_->holdObjectChoice(adapter_.anticipatingRest() && reach_.prediction().end_trusted);
  const perception::PerceptionEstimate& est = adapter_.anticipatingRest() ? led_ : *estimate_;
  control::Isometry torso;
  if (settings_.stand.declared) torso = torsoUnderShoulder(est.human.upper_arm.translation(), settings_.stand);
  planning_->update(est, control_in_.q, adapter_.payloadSet(), settings_.stand.declared ? &torso : nullptr);
  machine_->plan();  // the carry request of the last step, if any
}

void HandoverCycle::start(const io::ArmState& arm, bool holds_object) {
  if (holds_object) {
    adapter_.setGripper(0.0, machine_->params().gripForce(settings_.object.mass, machine_->context().comInTcp()));
    adapter_.setPayload(settings_.object.mass, settings_.object.com_in_tcp);
  } else {
    adapter_.setGripper(settings_.gripper_open_width, settings_.gripper_force);
  }
  control_in_.time = arm.time;
  control_in_.q = arm.q;
  control_in_.qd.setZero();
  controller_.reset(control_in_);
  control::Payload object;
  object.mass = settings_.object.mass;
  object.com = settings_.object.com_in_tcp;
  contact_.start(object, holds_object);
  reach_.reset();
  controller_.setPayload(contact_.payload());
  robot_held_ = adapter_.payloadSet();
}

const io::ArmCommand& HandoverCycle::step(double t, const io::ArmState& arm, perception::PoseSource& source) {
  // 1. perceive (who holds the object, and the TCP, as of the last cycle)
  estimator_.update(t, source);
  const bool robot_holds = adapter_.payloadSet();
  if (robot_held_ && !robot_holds && estimate_->human.valid) {
    // the robot let go: the object stays where the fingers left it in the person's
    // hand (not where a nominal grip would put it), for the collision rows after
    // the release, until a tracker measures the object itself
    estimator_.setHandObjectOffset(estimate_->human.hand.inverse() * controller_.tcpPose() *
                                   machine_->context().objectInTcp());
  }
  robot_held_ = robot_holds;
  const perception::PerceptionEstimate& est =
      estimator_.estimate(t, robot_holds ? perception::ObjectHolder::Robot : perception::ObjectHolder::Person,
                          controller_.tcpPose(), machine_->context().objectInTcp());  // the grasp closed on
  estimate_ = &est;

  // 2. velocities: the estimator's motion model when it has one, else differences of new samples
  if (est.human.valid) {
    if (est.human.has_velocity) hand_vel_.set(est.human.hand_velocity);
    else hand_vel_.update(est.human.stamp, est.human.hand);
    forearm_vel_.update(est.human.stamp, est.human.forearm);
    upper_arm_vel_.update(est.human.stamp, est.human.upper_arm);
  }
  if (est.object.valid && !robot_holds) {
    if (est.object.has_velocity) object_vel_.set(est.object.velocity);
    else object_vel_.update(est.human.stamp, est.object.pose);
  }

  // the same estimate with the hand (and the object it holds) where the reach will end
  if (predict_reach_) led_ = est;
  if (predict_reach_ && est.human.valid) {
    led_.human.hand = reach_.ledPose(est.human.hand, est.human.hand);
    if (est.object.valid && est.object.holder == perception::ObjectHolder::Person)
      led_.object.pose = reach_.ledPose(est.human.hand, est.object.pose);
  }

  // 3-4. the state machine, on this cycle's sensing and the last cycle's controller state
  adapter_.setTime(t);
  assembleInput(t, arm, est);
  machine_->step(input_);

  // 5. observation target
  const perception::TargetOutput& target = obs_target_.update(t, adapter_.anticipatingRest() ? led_ : est);
  controller_.setObservationTarget(target.pose,
                                   target.valid && adapter_.observationTarget() != fsm::ObservationTarget::kNone);

  // 6. collision environment: the perceived person
  control::CollisionEnvironment env;
  // a silent tracker does not make the place a person was free: they stay a while where the
  // estimator last put them (a receiver reaching at 0.85 m/s during a 0.5 s dropout met the
  // presenting arm, which had dropped them and moved on, g703_00117)
  env.person_valid =
      est.human.valid && (!est.human.stale || est.human.silence <= settings_.collision.person.unseen_hold);
  env.hand = est.human.hand;
  env.forearm = est.human.forearm;
  env.upper_arm = est.human.upper_arm;
  env.forearm_length = settings_.forearm_length;
  env.upper_arm_length = settings_.upper_arm_length;
  if (settings_.stand.declared) {
    env.torso = torsoUnderShoulder(est.human.upper_arm.translation(), settings_.stand);
    env.trunk_valid = env.person_valid;
  }
  env.hand_velocity = hand_vel_.velocity();
  // the forearm and upper arm move too: a damper that took them as still let a forearm coming at
  // 0.3 m/s into the open gripper while the arm approached beside it (the pair's distance fell 4 cm
  // while its rate read +0.2 m/s, g491_00039)
  env.forearm_velocity = forearm_vel_.velocity();
  env.upper_arm_velocity = upper_arm_vel_.velocity();
  // in the person's hand, it is as stale as the hand (perception_estimator.cpp)
  env.object_valid = est.object.valid && est.object.holder == perception::ObjectHolder::Person && env.person_valid;
  env.object = est.object.pose;
  env.object_velocity = object_vel_.velocity();
  if (forecast_hand_) {
    // once the reach's end is trusted at all (lead > 0, from about the speed peak)
    const perception::ReachPrediction& reach = reach_.prediction();
    env.hand_forecast_valid = reach.reaching && reach.lead > 0.0 && reach.end.matrix().allFinite();
    env.hand_forecast = reach.end;
  }
  if (collision_) collision_->setEnvironment(env);

  // 6b. the wrist load: the share the robot carries goes into the model, the rest is a known wrench
  control::ContactWrenchInput cw;
  cw.reading = -settings_.ft_gravity_sign * arm.wrench;
  cw.sensor_rotation = input_.ft_rotation;
  cw.sensor_acceleration = controller_.sensorAcceleration();
  cw.at_rest = arm.qd.norm() < settings_.controller.contact_wrench.rest_speed;
  cw.gripper_closed = adapter_.gripperWidth() < 0.5 * settings_.gripper_open_width;
  // the robot alone carries the object: the state machine set its payload, no
  // phase shares it with the person, and no hand of theirs is at the gripper
  // (the TCP of the last step, as the state machine read it)
  const bool hand_at_gripper =
      env.person_valid && (env.hand.translation() - input_.tcp_pose.translation()).norm() <
                              settings_.controller.contact_wrench.shared_distance;
  cw.carried_alone = adapter_.payloadSet() && !adapter_.handClearanceRelaxed() && !hand_at_gripper;
  control::Payload object;
  object.mass = settings_.object.mass;
  object.com = machine_->context().comInTcp();  // the grasp the state machine tracks or closed on
  contact_.setObject(object);
  contact_.update(cw);
  controller_.setPayload(contact_.payload());
  controller_.setExternalWrench(contact_.feedForward());
  // while carrying alone, the joint torque the model misses replaces the wrench; learnt only
  // then, held while a person may touch (disturbance_observer.hpp)
  controller_.setDisturbanceFeedback(contact_.disturbanceGain(), cw.carried_alone);

  // 7. the QP
  control_in_.time = t;
  control_in_.q = arm.q;
  control_in_.qd = arm.qd;
  command_.tau = controller_.step(control_in_);

  // 8. the command
  command_.gripper_width = adapter_.gripperWidth();
  command_.gripper_force = adapter_.gripperForce();
  return command_;
}

void HandoverCycle::assembleInput(double t, const io::ArmState& arm, const perception::PerceptionEstimate& est) {
  const bool robot_holds = adapter_.payloadSet();
  fsm::HandoverInput& in = input_;
  in.time = t;
  // this cycle's arm sensing
  in.q = arm.q;
  in.qd = arm.qd;
  in.joint_limit_margin =
      std::min((arm.q - controller_.model().q_min).minCoeff(), (controller_.model().q_max - arm.q).minCoeff());
  in.finger_width = arm.finger_width;
  in.wrench = arm.wrench;
  // the previous Controller::step's kinematics
  in.tcp_pose = controller_.tcpPose();
  in.tcp_velocity = controller_.tcpVelocity();
  const control::Isometry ft = control::framePlacement(controller_.model(), controller_.data(), ft_frame_);
  in.ft_rotation = ft.linear();
  // the load's torque moved from the sensor to the TCP: tau_tcp = tau_sensor - (p_tcp - p_sensor) x f
  const control::Vector6& load = contact_.load();
  in.tool_contact.head<3>() = load.head<3>();
  in.tool_contact.tail<3>() =
      load.tail<3>() - (in.tcp_pose.translation() - ft.translation()).cross(load.head<3>());
  in.load_share = contact_.loadShare();
  in.interaction_force = contact_.interactionForce();
  // this cycle's perception
  in.hand.pose = est.human.hand;
  in.hand.velocity = hand_vel_.velocity();
  in.hand.speed_std = est.human.hand_speed_std;  // 0 without a motion model
  in.hand.valid = est.human.valid && !est.human.stale;
  in.hand.age = est.human.valid ? est.human.silence : 1e9;  // a steady latency is not silence
  in.hand.stamp = est.human.valid ? est.human.stamp : -1.0;
  in.object.pose = est.object.pose;
  in.object.velocity = robot_holds ? controller_.tcpVelocity() : object_vel_.velocity();
  in.object.speed_std = robot_holds ? 0.0 : est.object.speed_std;
  in.object.valid = est.object.valid && !est.object.stale;
  in.object.age = robot_holds ? 0.0 : in.hand.age;
  in.object.stamp = robot_holds ? t : in.hand.stamp;  // sensed with the hand, or the TCP's now
  in.hand_open = robot_holds;
  // the object's end of reach (take); the receiver's hand in a give comes for the object, its
  // reach is not anticipated (Approach, docs/state-machine.md)
  in.object.rest_known = predict_reach_;
  if (predict_reach_) in.object.rest_pose = led_.object.pose;
  // the previous Controller::step's collision distances (perceived person)
  if (collision_) {
    const control::CollisionModel& cm = collision_->collisionModel();
    const control::CollisionData& cd = collision_->collisionData();
    in.hand_distance = clip(personDistance(cm, cd, hand_rule_, false, PersonPart::kHand));
    in.arm_distance = clip(personDistance(cm, cd, hand_rule_, false, PersonPart::kArm));
    in.person_constraint_engaged = personConstraintEngaged(cm, cd);
  } else {
    in.hand_distance = in.arm_distance = clip(std::numeric_limits<double>::infinity());  // no collision scene
    in.person_constraint_engaged = false;
  }
  in.human_distance = std::min(in.hand_distance, in.arm_distance);
  // the controller's observed object and tracking target, as commanded so far
  in.observed_target = adapter_.observationTarget();
  in.observed_pose = controller_.observedState().pose;
  in.observed_velocity = controller_.observedState().velocity;
  const control::GraspFrameState gf = controller_.graspFrame();
  in.target_pose = gf.pose;
  in.target_velocity = gf.velocity;
  in.holds_object = robot_holds;
  if (planning_) {
    in.object_plan = planning_->objectPlan();
    in.hand_plan = planning_->handPlan();
  }
}

}  // namespace handover::runtime
