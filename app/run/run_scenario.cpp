#include "app/run/run_scenario.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <thread>

#include "app/report/outcome_judge.hpp"
#include "app/run/controller_adapter.hpp"
#include "app/run/run_log.hpp"
#include "app/run/sensed_velocity.hpp"
#include "app/run/world_setup.hpp"
#include "config/input_error.hpp"
#include "control/collision/collision_config.hpp"
#include "control/collision/environment_from_sim.hpp"
#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_model.hpp"
#include "control/constraints/collision_constraint.hpp"
#include "control/controller.hpp"
#include "control/model/algorithms.hpp"
#include "fsm/handover/handover_fsm.hpp"
#include "perception/observation_target.hpp"
#include "perception/csv_pose_source.hpp"
#include "perception/perception_config.hpp"
#include "perception/udp_pose_source.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/simulated_pose_sensor.hpp"
#include "scenes/human/human_facts.hpp"
#include "scenes/human/scripted_human.hpp"
#include "scenes/human/two_link_arm.hpp"
#include "scenes/sim/simulation.hpp"

#ifdef HANDOVER_HAVE_RENDER
#include "app/render/interactive_viewer.hpp"
#include "app/render/video_recorder.hpp"
#endif

namespace handover::app {

namespace {

using Clock = std::chrono::steady_clock;

/// Which of the person's bodies a distance covers.
enum class PersonPart { kAll, kHand, kArm };

// The robot's gripper capsules (URDF link panda_hand and the fingers), and
// among them the fingertip capsule ("hand_b", between the fingers: it is
// where a held object sits). Named once here, from scenes/panda.urdf.
bool isGripperCapsule(const control::CollisionBody& b) {
  return b.link.rfind("panda_hand", 0) == 0 || b.link.find("finger") != std::string::npos;
}
bool isFingertipCapsule(const control::CollisionBody& b) {
  return isGripperCapsule(b) && b.name.find("hand_b") != std::string::npos;
}

/// Smallest robot-person distance over the active pairs of `cdata` (margins
/// added back: the true clearance), skipping pairs of rule `skip_rule` (-1:
/// none) and, when `skip_fingertips`, the fingertips (they hold the shared
/// object). The arm part leaves out the gripper: near the person's wrist it
/// is the handover itself, and its clearance is the collision constraint's job.
double personDistance(const control::CollisionModel& cm, const control::CollisionData& cd, int skip_rule,
                      bool skip_fingertips, PersonPart part = PersonPart::kAll) {
  double d = INFINITY;
  for (int i = 0; i < cm.numPairs(); ++i) {
    const auto& pair = cm.pairs[i];
    const auto& res = cd.results[i];
    if (!res.active || pair.rule == skip_rule) continue;
    const control::CollisionBody& other = cm.bodies[pair.other_body];
    if (!other.isPerson()) continue;
    const bool is_hand = other.kind == control::CollisionBodyKind::kHumanHand;
    if ((part == PersonPart::kHand && !is_hand) || (part == PersonPart::kArm && is_hand)) continue;
    const control::CollisionBody& robot = cm.bodies[pair.robot_body];
    if (skip_fingertips && isFingertipCapsule(robot)) continue;
    if (part == PersonPart::kArm && isGripperCapsule(robot)) continue;
    d = std::min(d, res.distance + pair.margin);
  }
  return d;
}

/// Smallest distance of the pairs whose other body is the table (table) or a robot body (self).
void tableAndSelfDistance(const control::CollisionModel& cm, const control::CollisionData& cd, double& table,
                          double& self) {
  table = self = INFINITY;
  for (int i = 0; i < cm.numPairs(); ++i) {
    const auto& res = cd.results[i];
    if (!res.active) continue;
    const auto& other = cm.bodies[cm.pairs[i].other_body];
    if (other.kind == control::CollisionBodyKind::kTable) table = std::min(table, res.distance);
    if (other.isRobot()) self = std::min(self, res.distance);
  }
}

double clip(double v) { return std::isfinite(v) ? std::min(v, 2.0) : 2.0; }

}  // namespace

RunSummary runScenario(const scenario::Scenario& sc, const RunOptions& opt) {
  const bool h2r = sc.mode == scenario::Mode::HumanToRobot;

  // -- build everything once (may throw InputError: bad input found late) ----
  control::Model model = control::loadModel(sourcePath("scenes/panda.urdf"));
  const control::ControllerConfig cfg =
      sc.config && !sc.config.IsNull()
          ? control::parseControllerConfig(YamlReader(sc.config, sc.config_path, ""))
          : control::loadControllerConfig(control::defaultControllerConfigPath());
  const control::CollisionConfig ccfg = control::loadCollisionConfig(control::defaultCollisionConfigPath());

  control::Controller controller(model, cfg);
  auto collision = std::make_shared<control::CollisionConstraint>(controller.model(), ccfg);
  controller.formulation().addConstraint(collision);

  // ground truth distances for the judge: same pairs, true person poses
  const control::CollisionModel truth_cm = control::buildCollisionModel(controller.model(), ccfg);
  control::CollisionData truth_cd(truth_cm);
  const int gripper_rule = collision->collisionModel().ruleIndex("person_hand_gripper");

  sim::Simulation sim;
  sim.load(simOptionsFor(sc));
  human::ScriptedHuman person(sc);
  perception::SimulatedPoseSensor sensor(sc.sensor, static_cast<std::uint64_t>(sc.seed));
  std::unique_ptr<perception::PoseSource> tracker;
  bool paced = false;
  if (!opt.tracker.empty()) {
    const std::string& spec = opt.tracker;
    if (spec.rfind("csv:", 0) == 0) {
      tracker = std::make_unique<perception::CsvPoseSource>(spec.substr(4));
    } else if (spec.rfind("udp:", 0) == 0) {
      int port = 0;
      try {
        port = std::stoi(spec.substr(4));
      } catch (const std::exception&) {
        port = -1;
      }
      if (port <= 0 || port > 65535) throw InputError("--tracker " + spec + ": expected udp:PORT with 1 <= PORT <= 65535");
      tracker = std::make_unique<perception::UdpPoseSource>(static_cast<std::uint16_t>(port));
      paced = true;
    } else {
      throw InputError("--tracker " + spec + ": expected csv:FILE or udp:PORT");
    }
  }
  const perception::PerceptionConfig pcfg =
      perception::loadPerceptionConfig(perception::defaultPerceptionConfigPath());
  perception::EstimatorSettings est_settings;
  est_settings.max_age = pcfg.max_age;
  est_settings.smoothing_time = pcfg.smoothing_time;
  est_settings.rotation_smoothing_time = pcfg.rotation_smoothing_time;
  est_settings.hand_T_object = sc.human.holds_object.value_or(Eigen::Isometry3d::Identity());
  perception::PerceptionEstimator estimator(est_settings);
  perception::ObservationTargetSettings target_settings;
  target_settings.blend_time = pcfg.blend_time;
  perception::ObservationTarget obs_target(target_settings);

  const control::GraspOffset grasp = graspOffsetFor(sc.object);
  ControllerAdapter adapter(controller, obs_target, grasp, 0.08);
  adapter.setCollision(collision.get(), gripper_rule);
  fsm::ObjectInfo object_info;
  object_info.mass = sc.object.mass;
  object_info.grasp_in_object = sc.object.grasp;
  object_info.com_in_tcp = sc.object.grasp.inverse().translation();
  auto machine = fsm::HandoverFsm::fromFile(fsm::HandoverFsm::defaultConfigPath(), adapter, object_info);

  // -- initial state --------------------------------------------------------
  const control::Vector7 q0 = sc.robot.start_q.value_or(cfg.posture.target);
  const Eigen::Isometry3d tcp_T_object = sc.object.grasp.inverse();
  const double hold_width = std::clamp(objectWidthAcrossFingers(sc.object), 0.0, 0.08);
  if (sc.robot.holds_object) {
    sim.reset(q0, hold_width, tcp_T_object);
    adapter.setGripper(0.0, 40.0);
    adapter.setPayload(sc.object.mass, object_info.com_in_tcp);
  } else {
    sim.reset(q0, 0.08);
    adapter.setGripper(0.08, 40.0);
  }
  {
    const human::HumanFacts facts = human::computeHumanFacts(sim.contacts(), sim.object(), sc.object,
                                                             sc.human.start);
    const human::HumanOutput& out0 = person.step(0.0, facts);
    sim.setHumanPoses(out0.poses);
    if (sc.human.holds_object) {
      sim.placeObject(out0.poses.hand * *sc.human.holds_object);
      sim.setObjectWeld(true);
    }
  }
  control::ControlInputs cin;
  cin.time = 0.0;
  cin.q = q0;
  cin.qd.setZero();
  controller.reset(cin);

  JudgeSettings js;
  js.mode = h2r ? "human_to_robot" : "robot_to_human";
  const double dt = sim.timestep();
  const std::size_t steps = static_cast<std::size_t>(std::ceil(sc.duration / dt)) + 1;
  OutcomeJudge judge(js, steps);
  RunLog log;
  log.reserve(steps / std::max(1, opt.log_every_ms) + 2);

  // output folders exist before anything is written into them
  if (!opt.out_dir.empty()) std::filesystem::create_directories(opt.out_dir);
  if (!opt.video_path.empty()) {
    const std::filesystem::path parent = std::filesystem::path(opt.video_path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
  }
#ifdef HANDOVER_HAVE_RENDER
  std::unique_ptr<render::VideoRecorder> video;
  if (!opt.video_path.empty()) {
    render::VideoOptions vo;
    vo.path = opt.video_path;
    video = std::make_unique<render::VideoRecorder>(sim.mujocoModel(), vo);
  }
  std::unique_ptr<render::ViewerWindow> viewer;
  if (opt.view) viewer = std::make_unique<render::ViewerWindow>(sim.mujocoModel());
#else
  if (!opt.video_path.empty() || opt.view) throw InputError("this build has no rendering (--video, --view)");
#endif

  SensedVelocity hand_vel, object_vel;
  const int ft_frame = controller.model().frameId("ft_sensor");
  const std::string* state = &machine->activePath();
  double done_at = -1.0;
  std::string error;
  const auto wall0 = Clock::now();
  double next_progress = 0.0;

  for (std::size_t k = 0; k < steps; ++k) {
    const double t = sim.time();

    // the person reacts to physical facts only
    const Eigen::Isometry3d hand_true = sim.humanHandPose();
    const sim::ContactReport contacts = sim.contacts();
    const sim::ObjectState obj_true = sim.object();
    const human::HumanFacts facts = human::computeHumanFacts(contacts, obj_true, sc.object, hand_true);
    human::HumanOutput hout = person.step(t, facts);
#ifdef HANDOVER_HAVE_RENDER
    // --view: a hand the user drags with the mouse replaces the script's hand;
    // the arm follows it as a two-link arm from the shoulder
    if (viewer && viewer->draggedPose() && viewer->draggedPose()->name == "human_hand") {
      const render::DraggedPose& dp = *viewer->draggedPose();
      hout.poses.hand.translation() = Eigen::Vector3d(dp.pos[0], dp.pos[1], dp.pos[2]);
      hout.poses.hand.linear() = Eigen::Quaterniond(dp.quat[0], dp.quat[1], dp.quat[2], dp.quat[3]).normalized().toRotationMatrix();
      const scenario::BodyDimensions body = person.body();
      const human::ArmPlacement arm_place =
          human::placeArm(person.shoulder(), hout.poses.hand.translation(),
                          human::ArmLengths{body.upper_arm, body.forearm, body.wrist_to_grip}, person.elbowHint());
      hout.poses.upper_arm = arm_place.upper_arm;
      hout.poses.forearm = arm_place.forearm;
    }
#endif
    sim.setHumanPoses(hout.poses);
    if (hout.holds_object != sim.objectWelded()) sim.setObjectWeld(hout.holds_object);

    // sensing and perception (estimates only)
    if (tracker) {
      estimator.update(t, *tracker);
    } else {
      sensor.observe(t, hout.poses);
      estimator.update(t, sensor);
    }
    const sim::ArmState arm = sim.armState();
    const bool robot_holds = adapter.payloadSet();
    const perception::PerceptionEstimate& est =
        estimator.estimate(t, robot_holds ? perception::ObjectHolder::Robot : perception::ObjectHolder::Person,
                           controller.tcpPose(), tcp_T_object);
    if (tracker && est.human.valid) {
      // the simulated person's body follows the tracked person (the script
      // still decides when the hand holds or lets go)
      hout.poses.hand = est.human.hand;
      hout.poses.forearm = est.human.forearm;
      hout.poses.upper_arm = est.human.upper_arm;
      sim.setHumanPoses(hout.poses);
      // a tracked object sits in the grip where the tracker saw it
      if (estimator.objectTracked() && sim.objectWelded() && !robot_holds) {
        sim.setObjectGrip(est.human.hand.inverse() * est.object.pose);
      }
    }
    if (est.human.valid) hand_vel.update(est.human.stamp, est.human.hand);
    if (est.object.valid && !robot_holds) object_vel.update(est.human.stamp, est.object.pose);

    // state machine (commands the controller through the adapter)
    const auto c0 = Clock::now();
    adapter.setTime(t);
    const control::Data& cdata = controller.data();
    fsm::HandoverInput in;
    in.time = t;
    in.q = arm.q;
    in.qd = arm.qd;
    in.tcp_pose = controller.tcpPose();
    in.tcp_velocity = controller.tcpVelocity();
    in.finger_width = arm.finger_width;
    in.wrench = arm.wrench;
    in.ft_rotation = control::framePlacement(controller.model(), cdata, ft_frame).linear();
    in.hand.pose = est.human.hand;
    in.hand.velocity = hand_vel.velocity();
    in.hand.valid = est.human.valid && !est.human.stale;
    in.hand.age = est.human.valid ? est.human.age : 1e9;
    in.object.pose = est.object.pose;
    in.object.velocity = robot_holds ? controller.tcpVelocity() : object_vel.velocity();
    in.object.valid = est.object.valid && !est.object.stale;
    in.object.age = robot_holds ? 0.0 : in.hand.age;
    in.hand_open = robot_holds;
    const control::CollisionModel& ccm = collision->collisionModel();
    const control::CollisionData& ccd = collision->collisionData();
    in.hand_distance = clip(personDistance(ccm, ccd, gripper_rule, false, PersonPart::kHand));
    in.arm_distance = clip(personDistance(ccm, ccd, gripper_rule, false, PersonPart::kArm));
    in.human_distance = std::min(in.hand_distance, in.arm_distance);
    in.observed_target = adapter.observationTarget();
    in.observed_pose = controller.observedState().pose;
    in.observed_velocity = controller.observedState().velocity;
    const control::GraspFrameState gf = controller.graspFrame();
    in.target_pose = gf.pose;
    in.target_velocity = gf.velocity;
    in.holds_object = robot_holds;
    machine->step(in);
    state = &machine->activePath();

    // observation target and collision environment, then the QP
    const perception::TargetOutput& target = obs_target.update(t, est);
    controller.setObservationTarget(target.pose, target.valid && adapter.observationTarget() != fsm::ObservationTarget::kNone);
    control::CollisionEnvironment env;
    env.person_valid = est.human.valid && !est.human.stale;
    env.hand = est.human.hand;
    env.forearm = est.human.forearm;
    env.upper_arm = est.human.upper_arm;
    env.forearm_length = hout.poses.forearm_length;
    env.upper_arm_length = hout.poses.upper_arm_length;
    env.hand_velocity = hand_vel.velocity();
    collision->setEnvironment(env);
    cin.time = t;
    cin.q = arm.q;
    cin.qd = arm.qd;
    const control::Vector7 tau = controller.step(cin);
    const double step_us = std::chrono::duration<double, std::micro>(Clock::now() - c0).count();

    sim::ArmCommand cmd;
    cmd.tau = tau;
    cmd.gripper_width = adapter.gripperWidth();
    cmd.gripper_force = adapter.gripperForce();
    sim.applyCommand(cmd);

    // judge on ground truth
    const control::CollisionEnvironment truth_env = control::environmentFromHuman(hout.poses);
    control::updateCollisions(truth_cm, truth_cd, controller.model(), controller.data(), truth_env);
    const bool a_finger_on = contacts.left_finger_on_object || contacts.right_finger_on_object;
    const double d_human = personDistance(truth_cm, truth_cd, -1, a_finger_on);
    StepFacts f;
    f.time = t;
    f.robot_human_contacts = contacts.robot_human;
    f.left_finger_on_object = contacts.left_finger_on_object;
    f.right_finger_on_object = contacts.right_finger_on_object;
    f.object_on_table = contacts.object_on_table;
    f.object_on_floor = contacts.object_on_floor;
    f.hand_holds_object = sim.objectWelded();
    f.object_pos = obj_true.pose.translation();
    f.object_vel = obj_true.velocity.head<3>();
    f.hand_pos = hout.poses.hand.translation();
    // with a tracker the person's hand is the tracked one (hand_still_to_grasp)
    f.hand_speed = tracker ? hand_vel.velocity().head<3>().norm() : hout.hand_speed;
    f.finger_width = arm.finger_width;
    f.min_human_distance = std::isfinite(d_human) ? d_human : 1e9;
    const Eigen::Isometry3d grasp_true = obj_true.pose * sc.object.grasp;
    const Eigen::Isometry3d tcp_true = sim.tcpPose();
    f.grasp_pos_error = (tcp_true.translation() - grasp_true.translation()).norm();
    if (grasp.has_free_axis) {
      // only the approach axis matters around a symmetry axis
      const Eigen::Vector3d a = (obj_true.pose.linear() * grasp.free_axis).normalized();
      const Eigen::Vector3d b = (tcp_true.linear() * sc.object.grasp.linear().transpose() * grasp.free_axis).normalized();
      f.grasp_rot_error_deg = std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / M_PI;
    } else {
      f.grasp_rot_error_deg = Eigen::AngleAxisd(tcp_true.linear().transpose() * grasp_true.linear()).angle() * 180.0 / M_PI;
    }
    f.gripper_closing = adapter.gripperWidth() < hold_width;
    const control::Model& m = controller.model();
    for (int j = 0; j < 7; ++j) {
      f.position_violation |= arm.q[j] < m.q_min[j] - 1e-6 || arm.q[j] > m.q_max[j] + 1e-6;
      f.velocity_violation |= std::abs(arm.qd[j]) > m.v_max[j] + 1e-6;
      f.torque_violation |= std::abs(tau[j]) > m.tau_max[j] + 1e-6;
    }
    f.qp_failed = controller.lastStepFellBack();
    f.state = state;
    f.step_us = step_us;
    judge.observe(f);

    if (opt.log_every_ms > 0 && k % static_cast<std::size_t>(opt.log_every_ms) == 0) {
      log.begin(t, *state);
      log.put(target.valid ? 1.0 : 0.0);
      log.putPose(target.pose);
      log.putPose(controller.observedState().pose);
      log.putPose(gf.pose);
      log.putPose(controller.tcpPose());
      for (int i = 0; i < 3; ++i) log.put(hout.poses.hand.translation()[i]);
      log.put(hout.hand_speed);
      for (int i = 0; i < 3; ++i) log.put(obj_true.pose.translation()[i]);
      log.putVec(arm.q.data(), 7);
      log.putVec(arm.qd.data(), 7);
      log.putVec(tau.data(), 7);
      for (int j = 0; j < 7; ++j) log.put(std::min(arm.q[j] - m.q_min[j], m.q_max[j] - arm.q[j]));
      double d_table = 0.0, d_self = 0.0;
      tableAndSelfDistance(truth_cm, truth_cd, d_table, d_self);
      log.put(clip(d_human));
      log.put(clip(d_table));
      log.put(clip(d_self));
      log.putVec(arm.wrench.data(), 6);
      log.put(arm.finger_width);
      log.put(adapter.gripperWidth());
      log.put(adapter.speedScale());
      log.put(static_cast<double>(controller.lastStatus()));
      log.put(controller.lastIterations());
      log.end();
    }

#ifdef HANDOVER_HAVE_RENDER
    if (video && video->wantsFrame(t)) video->addFrame(sim.mujocoModel(), sim.mujocoDataForRendering(), *state);
    if (viewer && !viewer->frame(sim.mujocoModel(), sim.mujocoDataForRendering(), *state)) break;
#endif

    sim.step();
    if (paced) {
      // a live tracker speaks in wall-clock time: do not outrun it
      const auto due = wall0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(t + dt));
      std::this_thread::sleep_until(due);
    }

    if (opt.progress && t >= next_progress) {
      opt.progress(t, sc.duration);
      next_progress = t + 0.1;
    }
    if (machine->done()) {
      if (done_at < 0.0) done_at = t;
      if (t - done_at >= opt.linger) break;
    }
  }
  machine->stop();
  const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();

#ifdef HANDOVER_HAVE_RENDER
  if (video) video->close();
#endif

  const fsm::HandoverStats& st = machine->stats();
  RunSummary r = judge.finish(machine->done(), st.outcome, st.handovers, st.aborts, st.retries, wall);
  r.scenario = sc.name;
  if (r.total_time && done_at >= 0.0) r.total_time = done_at;
  r.expectation_failures = checkExpectations(sc, r);

  if (!opt.out_dir.empty()) {
    std::filesystem::create_directories(opt.out_dir);
    const std::string summary_path = opt.out_dir + "/summary.json";
    std::ofstream(summary_path) << r.toJson();
    if (opt.log_every_ms > 0) log.write(opt.out_dir + "/log.csv");
  }
  return r;
}

std::vector<std::string> checkExpectations(const scenario::Scenario& sc, const RunSummary& r) {
  std::vector<std::string> bad;
  const auto& e = sc.expect;
  auto fmt = [](double v) {
    std::ostringstream os;
    os << v;
    return os.str();
  };
  if (e.outcome && *e.outcome != r.outcome) bad.push_back("outcome: expected " + *e.outcome + ", got " + r.outcome);
  if (e.aborts && *e.aborts != r.aborts)
    bad.push_back("aborts: expected " + std::to_string(*e.aborts) + ", got " + std::to_string(r.aborts));
  if (e.retries && *e.retries != r.retries)
    bad.push_back("retries: expected " + std::to_string(*e.retries) + ", got " + std::to_string(r.retries));
  if (e.handovers && *e.handovers != r.handovers)
    bad.push_back("handovers: expected " + std::to_string(*e.handovers) + ", got " + std::to_string(r.handovers));
  if (e.max_total_time && !(r.total_time && *r.total_time <= *e.max_total_time))
    bad.push_back("max_total_time: expected <= " + fmt(*e.max_total_time) + " s, got " +
                  (r.total_time ? fmt(*r.total_time) + " s" : std::string("none")));
  if (e.min_human_distance && !(r.min_human_distance >= *e.min_human_distance))
    bad.push_back("min_human_distance: expected >= " + fmt(*e.min_human_distance) + " m, got " +
                  fmt(r.min_human_distance) + " m");
  if (e.max_time_to_grasp && !(r.time_to_grasp && *r.time_to_grasp <= *e.max_time_to_grasp))
    bad.push_back("max_time_to_grasp: expected <= " + fmt(*e.max_time_to_grasp) + " s, got " +
                  (r.time_to_grasp ? fmt(*r.time_to_grasp) + " s" : std::string("none")));
  if (e.max_human_contacts && r.human_contacts > *e.max_human_contacts)
    bad.push_back("max_human_contacts: expected <= " + std::to_string(*e.max_human_contacts) + ", got " +
                  std::to_string(r.human_contacts));
  if (e.object_dropped && *e.object_dropped != r.object_dropped)
    bad.push_back(std::string("object_dropped: expected ") + (*e.object_dropped ? "true" : "false"));
  return bad;
}

std::string formatSummary(const RunSummary& r) {
  std::ostringstream os;
  auto opt = [](const std::optional<double>& v, const char* unit) {
    if (!v) return std::string("-");
    char b[32];
    std::snprintf(b, sizeof b, "%.3f %s", *v, unit);
    return std::string(b);
  };
  char line[160];
  os << "scenario   " << r.scenario << " (" << r.mode << ")\n";
  os << "outcome    " << r.outcome << (r.error_message.empty() ? "" : ": " + r.error_message) << "\n";
  os << "counts     handovers " << r.handovers << ", aborts " << r.aborts << ", retries " << r.retries << "\n";
  os << "timing     grasp at " << opt(r.time_to_grasp, "s") << ", hand still to grasp "
     << opt(r.hand_still_to_grasp, "s") << ", total " << opt(r.total_time, "s") << "\n";
  std::snprintf(line, sizeof line, "safety     min distance to person %.3f m, contacts %d, dropped %s\n",
                r.min_human_distance, r.human_contacts, r.object_dropped ? "yes" : "no");
  os << line;
  std::snprintf(line, sizeof line, "limits     position %d, velocity %d, torque %d steps; QP failures %d\n",
                r.limit_violations.position, r.limit_violations.velocity, r.limit_violations.torque, r.qp_failures);
  os << line;
  if (r.grasp_error_pos) {
    std::snprintf(line, sizeof line, "grasp      error %.1f mm, %.1f deg\n", *r.grasp_error_pos * 1000.0,
                  r.grasp_error_rot_deg.value_or(0.0));
    os << line;
  }
  std::snprintf(line, sizeof line, "compute    control step median %.1f us, p99 %.1f us, max %.1f us; %.1fx real time\n",
                r.control_step_us.median, r.control_step_us.p99, r.control_step_us.max, r.realtime_factor);
  os << line;
  os << "states     ";
  for (std::size_t i = 0; i < r.states.size(); ++i) os << (i ? " > " : "") << r.states[i];
  os << "\n";
  for (const auto& e : r.expectation_failures) os << "EXPECTED   " << e << "\n";
  return os.str();
}

}  // namespace handover::app
