#include "app/run/run_scenario.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "app/report/outcome_judge.hpp"
#include "app/report/output_files.hpp"
#include "app/run/fallback_budget.hpp"
#include "app/run/run_log.hpp"
#include "app/run/world_setup.hpp"
#include "app/validate/person_trunk.hpp"
#include "scenes/human/plausible_follower.hpp"
#include "scenes/scenario/object_geometry.hpp"
#include "app/validate/scenario_validation.hpp"
#include "config/input_error.hpp"
#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_model.hpp"
#include "control/collision/environment_from_human.hpp"
#include "perception/csv_pose_source.hpp"
#include "perception/simulated_pose_sensor.hpp"
#include "perception/udp_pose_source.hpp"
#include "runtime/collision_queries.hpp"
#include "runtime/handover_cycle.hpp"
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

using runtime::personDistance;
using runtime::tableAndSelfDistance;

double clip(double v) { return std::isfinite(v) ? std::min(v, 2.0) : 2.0; }

// m: the judge's true-clearance query stops here; a person farther away reads
// as "far" (infinite, as before: null in summary.json, 2 in log.csv)
constexpr double kClearanceCap = 0.5;

}  // namespace

RunSummary runScenario(const scenario::Scenario& sc, const RunOptions& opt) {
  validateScenario(sc);  // the same checks as `handover check`
  const bool h2r = sc.mode == scenario::Mode::HumanToRobot;

  // -- build everything once (may throw InputError: bad input found late) ----
  runtime::CycleSettings cs = runtime::defaultCycleSettings();
  if (sc.config && !sc.config.IsNull()) cs.controller = control::parseControllerConfig(YamlReader(sc.config, sc.config_path, ""));
  cs.estimator.hand_T_object = sc.human.holds_object.value_or(Eigen::Isometry3d::Identity());
  // the object as the robot holds it: a give's declared grasp deeper than the
  // palm lets the object sit is held in front of the palm (the simulator and
  // the controller both), never with the object inside the hand
  const scenario::ObjectSpec held = robotHeldObject(sc, cs.grasp_selection.palm);
  cs.object.mass = sc.object.mass;
  cs.object.grasp_in_object = held.grasp;
  cs.object.com_in_tcp = held.grasp.inverse().translation();
  cs.object.shape = scenario::primitiveShapeOf(sc.object);
  cs.object_grasp = graspOffsetFor(held);
  cs.object_grasps = graspSpecsFor(sc.object, cs.grasp_selection.declared_preference, cs.gripper_open_width,
                                   cs.grasp_selection.palm);
  cs.collision.object = collisionShapeFor(sc.object);
  human::ScriptedHuman person(sc);
  const scenario::BodyDimensions body = person.body();
  cs.forearm_length = body.forearm;
  cs.upper_arm_length = body.upper_arm;
  // the trunk: sized from the stature, placed from the tracked shoulder and the declared stand
  cs.collision.person.trunk = personTrunkFor(body, sc.human.hand);
  cs.stand.declared = true;
  cs.stand.yaw = sc.human.stand_yaw;
  cs.stand.shoulder_side = (sc.human.hand == scenario::HandSide::Right ? 1.0 : -1.0) * body.shoulder_offset;
  runtime::HandoverCycle cycle(cs);
  const control::Controller& controller = cycle.controller();
  const runtime::ControllerAdapter& adapter = cycle.adapter();
  const fsm::HandoverFsm& machine = cycle.machine();

  // ground truth distances for the judge: same pairs, true person poses
  const control::CollisionModel truth_cm = control::buildCollisionModel(controller.model(), cs.collision);
  control::CollisionData truth_cd(truth_cm);

  sim::Simulation sim;
  sim.load(simOptionsFor(sc));
  perception::SimulatedPoseSensor sensor(sc.sensor, static_cast<std::uint64_t>(sc.seed));
  std::unique_ptr<perception::PoseSource> tracker;
  bool paced = false;
  const perception::UdpPoseSource* udp = nullptr;  // for its count of malformed datagrams
  if (!opt.tracker.empty()) {
    const std::string& spec = opt.tracker;
    if (spec.rfind("csv:", 0) == 0) {
      tracker = std::make_unique<perception::CsvPoseSource>(spec.substr(4));
    } else if (spec.rfind("udp:", 0) == 0) {
      int port = 0;
      try {
        std::size_t used = 0;
        port = std::stoi(spec.substr(4), &used);
        if (used != spec.size() - 4 || !std::isdigit(static_cast<unsigned char>(spec[4]))) port = -1;  // "22x", " 22"
      } catch (const std::exception&) {
        port = -1;
      }
      if (port <= 0 || port > 65535) throw InputError("--tracker " + spec + ": expected udp:PORT with 1 <= PORT <= 65535");
      auto source = std::make_unique<perception::UdpPoseSource>(static_cast<std::uint16_t>(port));
      udp = source.get();
      tracker = std::move(source);
      paced = true;
    } else {
      throw InputError("--tracker " + spec + ": expected csv:FILE or udp:PORT");
    }
  }
  perception::PoseSource& source = tracker ? *tracker : static_cast<perception::PoseSource&>(sensor);

  // a tracked person drives the simulated bodies as fast as a hand can (never a teleport)
  human::PlausibleFollower follower(person.limits(), sim.timestep());
  sim::HumanBodyPoses tracked;   // the tracked person's last valid poses
  bool ever_tracked = false;

  // -- initial state --------------------------------------------------------
  const control::Vector7 q0 = sc.robot.start_q.value_or(cs.controller.posture.target);
  const Eigen::Isometry3d tcp_T_object = held.grasp.inverse();
  const double hold_width = std::clamp(scenario::objectWidthAcrossFingers(sc.object), 0.0, cs.gripper_open_width);
  if (sc.robot.holds_object) sim.reset(q0, hold_width, tcp_T_object);
  else sim.reset(q0, cs.gripper_open_width);
  {
    io::ArmState arm0;
    arm0.q = q0;
    cycle.start(arm0, sc.robot.holds_object);
  }
  {
    const human::HumanFacts facts = human::computeHumanFacts(sim.contacts(), sim.object(), sc.object,
                                                             sc.human.start);
    const human::HumanOutput& out0 = person.step(0.0, facts);
    sim.setHumanPoses(out0.poses);
    tracked = out0.poses;
    if (sc.human.holds_object) {
      sim.placeObject(out0.poses.hand * *sc.human.holds_object);
      sim.setObjectWeld(true);
    }
  }

  JudgeSettings js;
  js.mode = h2r ? "human_to_robot" : "robot_to_human";
  const double dt = sim.timestep();
  const std::size_t steps = static_cast<std::size_t>(std::ceil(sc.duration / dt)) + 1;
  OutcomeJudge judge(js, steps);
  RunLog log;
  log.reserve(steps / std::max(1, opt.log_every_ms) + 2);
  if (cycle.hasCollision()) {
    const control::CollisionModel& cm = cycle.collision().collisionModel();
    std::vector<std::string> labels;
    for (int k = 0; k < cm.numPairs(); ++k) labels.push_back(cm.pairLabel(k));
    log.setLabels(std::move(labels));
  }

  // output folders exist and take writes before the simulation starts
  if (!opt.out_dir.empty()) prepareOutputDir(opt.out_dir);
  if (!opt.video_path.empty()) checkVideoPath(opt.video_path);
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

  const control::GraspOffset& grasp = cs.object_grasp;
  const std::string* state = &machine.activePath();
  double done_at = -1.0;
  std::string error;
  std::string stopped;  // why an unsafe run was stopped early ("" if not)
  FallbackBudget fallback_budget(cs.controller.fallback.window, dt, cs.controller.fallback.max_share);
  const auto wall0 = Clock::now();
  double next_progress = 0.0;

  try {
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
        const human::ArmPlacement arm_place =
            human::placeArm(person.shoulder(), hout.poses.hand.translation(),
                            human::ArmLengths{body.upper_arm, body.forearm, body.wrist_to_grip}, person.elbowHint());
        hout.poses.upper_arm = arm_place.upper_arm;
        hout.poses.forearm = arm_place.forearm;
      }
#endif
      sim.setHumanPoses(hout.poses);
      if (hout.holds_object != sim.objectWelded()) sim.setObjectWeld(hout.holds_object);

      // the simulated pose sensor sees the person; the arm reports its state
      if (!tracker) sensor.observe(t, hout.poses);
      const sim::ArmState arm = sim.state();

      // the control cycle: perception, state machine, QP
      cycle.plan();  // the planning stage: outside the timed 1 ms step (handover_cycle.hpp)
      const auto c0 = Clock::now();
      const io::ArmCommand& cmd = cycle.step(t, arm, source);
      const double step_us = std::chrono::duration<double, std::micro>(Clock::now() - c0).count();
      sim.apply(cmd);
      state = &machine.activePath();
      const perception::PerceptionEstimate& est = cycle.estimate();
      if (tracker) {
        // the simulated person's body follows the tracked person (the script
        // still decides when the hand holds or lets go), as a body can: a
        // tracked jump is followed at a hand's speed, never teleported. It
        // appears where the tracker first sees it and, unseen, stays where
        // it was last seen
        if (est.human.valid) {
          tracked.hand = est.human.hand;
          tracked.forearm = est.human.forearm;
          tracked.upper_arm = est.human.upper_arm;
          if (!ever_tracked) follower.reset(tracked);
          ever_tracked = true;
        }
        if (ever_tracked) {
          tracked.torso = hout.poses.torso;
          hout.poses = follower.step(tracked);
          sim.setHumanPoses(hout.poses);
        }
      }
      if (tracker && est.human.valid) {
        // a tracked object sits in the grip where the tracker saw it
        if (cycle.objectTracked() && sim.objectWelded() && !adapter.payloadSet()) {
          sim.setObjectGrip(est.human.hand.inverse() * est.object.pose);
        }
      }
      if (controller.lastStepFellBack() &&
          (controller.fallbackStreak() == 1 || controller.fallbackStreak() % 1000 == 0))
        std::fprintf(stderr, "controller: t=%.3f s: QP %s%s%s; damped stop (fallback %ld)\n", t,
                     control::toString(controller.lastStatus()), controller.lastFallbackReason()[0] ? ": " : "",
                     controller.lastFallbackReason(), controller.fallbackCount());
      const control::Vector7& tau = cmd.tau;

      // judge on ground truth: the simulated robot's and person's own geometry
      // (hand, arms, torso, legs, head), at the state the contact list describes
      const control::CollisionEnvironment truth_env = control::environmentFromHuman(hout.poses);
      control::updateCollisions(truth_cm, truth_cd, controller.model(), controller.data(), truth_env);
      const bool a_finger_on = contacts.left_finger_on_object || contacts.right_finger_on_object;
      const sim::PersonClearance clearance = sim.personClearance(kClearanceCap);
      const double d_near = a_finger_on ? clearance.without_fingers : clearance.all;
      const double d_human = d_near < kClearanceCap ? d_near : INFINITY;
      StepFacts f;
      f.time = t;
      f.robot_human_contacts = contacts.robot_human;
      f.human_penetration = clearance.all < 0.0;
      f.left_finger_on_object = contacts.left_finger_on_object;
      f.right_finger_on_object = contacts.right_finger_on_object;
      f.object_on_table = contacts.object_on_table;
      f.object_on_floor = contacts.object_on_floor;
      f.hand_holds_object = sim.objectWelded();
      f.object_pos = obj_true.pose.translation();
      f.object_vel = obj_true.velocity.head<3>();
      f.hand_pos = hout.poses.hand.translation();
      // with a tracker the person's hand is the tracked one (hand_still_to_grasp)
      f.hand_speed = tracker ? cycle.handVelocity().head<3>().norm() : hout.hand_speed;
      f.finger_width = arm.finger_width;
      f.min_human_distance = std::isfinite(d_human) ? d_human : 1e9;
      // judged against the grasp the robot chose (one of the families the object
      // admits), the declared one without a planner
      const fsm::TrackedChoice& chosen = cycle.machine().context().grasp;
      const Eigen::Isometry3d grasp_in_object = chosen.planned ? chosen.offset : held.grasp;
      const Eigen::Isometry3d grasp_true = obj_true.pose * grasp_in_object;
      const Eigen::Isometry3d tcp_true = sim.tcpPose();
      f.grasp_pos_error = (tcp_true.translation() - grasp_true.translation()).norm();
      if (grasp.has_free_axis) {
        // only the approach axis matters around a symmetry axis
        const Eigen::Vector3d a = (obj_true.pose.linear() * grasp.free_axis).normalized();
        const Eigen::Vector3d b = (tcp_true.linear() * grasp_in_object.linear().transpose() * grasp.free_axis).normalized();
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
      f.qp_relaxed = controller.lastStepRelaxed();
      f.person_seen = est.human.valid && !est.human.stale;
      f.limit_guarded = controller.lastStepGuarded();
      f.state = state;
      f.step_us = step_us;
      judge.observe(f);

      if (opt.log_every_ms > 0 && k % static_cast<std::size_t>(opt.log_every_ms) == 0) {
        const perception::TargetOutput& target = cycle.target();
        log.begin(t, *state);
        log.put(target.valid ? 1.0 : 0.0);
        log.putPose(target.pose);
        log.putPose(controller.observedState().pose);
        log.putPose(cycle.fsmInput().target_pose);  // the tracking target the state machine saw (before the QP)
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
        const control::ContactWrenchEstimator& cw = cycle.contactWrench();
        log.put(cw.loadShare());
        log.putVec(cw.load().data(), 3);
        log.putVec(cw.feedForward().data(), 3);
        log.put(adapter.gripperForce());
        log.put(controller.lastSlack());
        log.put(f.person_seen ? 1.0 : 0.0);
        perception::RejectCounts rejects = cycle.rejects();
        if (udp) rejects.add(perception::RejectReason::kMalformed, udp->malformed());
        for (long n : rejects.count) log.put(static_cast<double>(n));
        log.put(static_cast<double>(controller.guardCount()));
        log.put(f.robot_human_contacts > 0 || f.human_penetration ? 1.0 : 0.0);
        control::NearestPair nearest;
        if (cycle.hasCollision())
          nearest = control::nearestToSafetyDistance(cycle.collision().collisionModel(), cycle.collision().collisionData());
        log.put(nearest.pair >= 0 ? nearest.gap : std::numeric_limits<double>::quiet_NaN());
        log.putLabel(nearest.pair);
        log.end();
      }

#ifdef HANDOVER_HAVE_RENDER
      if (video && video->wantsFrame(t)) video->addFrame(sim.mujocoModel(), sim.mujocoDataForRendering(), *state);
      if (viewer && !viewer->frame(sim.mujocoModel(), sim.mujocoDataForRendering(), *state)) break;
#endif

      sim.step();
      // a diverged simulator has reset its world: nothing after it is physics
      if (sim.diverged()) throw std::runtime_error(sim.divergenceMessage());
      // a controller that keeps failing its QP holds the arm in the damped stop: nothing follows
      if (fallback_budget.observe(controller.lastStepFellBack())) {
        char why[200];
        std::snprintf(why, sizeof why,
                      "stopped at t = %.3f s: the QP failed in %d of the last %zu steps (fallback.max_share %.2f); "
                      "the arm was held by the damped stop",
                      t, fallback_budget.count(), fallback_budget.windowSteps(), cs.controller.fallback.max_share);
        stopped = why;
        break;
      }
      if (paced) {
        // a live tracker speaks in wall-clock time: do not outrun it
        const auto due = wall0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(t + dt));
        std::this_thread::sleep_until(due);
      }

      if (opt.progress && t >= next_progress) {
        opt.progress(t, sc.duration);
        next_progress = t + 0.1;
      }
      if (machine.done()) {
        if (done_at < 0.0) done_at = t;
        if (t - done_at >= opt.linger) break;
      }
    }
  } catch (const InputError&) {
    throw;  // bad input found late stays bad input (exit code 2)
  } catch (const std::exception& e) {
    // a fault during the run (simulator, tracker, controller) ends it with
    // outcome "error"; what was logged so far is still written
    error = e.what();
  }
  cycle.stop();
  const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();

#ifdef HANDOVER_HAVE_RENDER
  if (video) video->close();
#endif

  const fsm::HandoverStats& st = machine.stats();
  RunSummary r = judge.finish(machine.done(), st.outcome, st.handovers, st.aborts, st.retries, wall);
  r.scenario = sc.name;
  if (r.total_time && done_at >= 0.0) r.total_time = done_at;
  if (!error.empty()) {
    r.outcome = "error";
    r.error_message = error;
  } else if (!stopped.empty()) {
    r.error_message = stopped;  // the outcome stays as judged (unsafe: the QP failed)
  }
  r.tracker = tracker ? (udp ? "udp" : "csv") : "simulated";
  perception::RejectCounts rejects = cycle.rejects();
  if (udp) rejects.add(perception::RejectReason::kMalformed, udp->malformed());
  r.rejected_samples = rejects.total();
  for (int k = 0; k < perception::kRejectReasons; ++k) {
    const auto why = static_cast<perception::RejectReason>(k);
    r.rejected_by_reason.emplace_back(perception::toString(why), rejects[why]);
  }
  if (follower.slowedSteps() > 0) {
    char b[320];
    std::snprintf(b, sizeof b,
                  "the tracked person moved faster than a hand can (%.1f m/s, %.0f m/s^2, %.0f rad/s) in %ld steps, "
                  "by up to %.3f m: the simulated person followed as fast as a hand can",
                  person.limits().max_speed, person.limits().max_acceleration, person.limits().max_angular_speed,
                  follower.slowedSteps(), follower.largestGap());
    r.person_slowed.emplace_back(b);
  }
  for (const human::StretchedStep& st : person.stretchedSteps()) {
    const scenario::ScriptStep& step = sc.human.script[st.step];
    char b[320];
    std::snprintf(b, sizeof b,
                  "script step %d (line %d) moves the hand %.3f m and turns it %.2f rad in %.3f s, faster than a "
                  "hand can (%.1f m/s, %.0f m/s^2, %.0f rad/s): the simulated person took %.3f s",
                  st.step + 1, step.where.line, st.distance, st.angle, st.written, person.limits().max_speed,
                  person.limits().max_acceleration, person.limits().max_angular_speed, st.used);
    r.person_slowed.emplace_back(b);
  }
  r.expectation_failures = checkExpectations(sc, r);

  if (!opt.out_dir.empty()) {
    writeFileChecked(opt.out_dir + "/summary.json", r.toJson());
    if (opt.log_every_ms > 0) log.write(opt.out_dir + "/log.csv");
  }
  return r;
}

}  // namespace handover::app
