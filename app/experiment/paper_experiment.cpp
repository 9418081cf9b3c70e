#include "app/experiment/paper_experiment.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/experiment/experiment_log.hpp"
#include "config/input_error.hpp"
#include "control/controller.hpp"
#include "perception/perception_config.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/simulated_pose_sensor.hpp"
#include "scenes/human/human_facts.hpp"
#include "scenes/human/scripted_human.hpp"
#include "scenes/sim/simulation.hpp"

namespace handover::app {

const char* toString(ReachController c) { return c == ReachController::kMethod ? "method" : "baseline"; }

ReachController parseReachController(const std::string& name) {
  if (name == "method") return ReachController::kMethod;
  if (name == "baseline") return ReachController::kBaseline;
  throw InputError("unknown controller '" + name + "' (expected method or baseline)");
}

const char* toString(Execution e) { return e == Execution::kTorque ? "torque" : "reference"; }

Execution parseExecution(const std::string& name) {
  if (name == "torque") return Execution::kTorque;
  if (name == "reference") return Execution::kJointReference;
  throw InputError("unknown execution '" + name + "' (expected torque or reference)");
}

namespace {

std::string sourcePath(const std::string& rel) { return std::string(HANDOVER_SOURCE_DIR) + "/" + rel; }

sim::SimOptions simOptionsFor(const scenario::Scenario& sc) {
  sim::SimOptions o;
  switch (sc.object.shape) {
    case scenario::Shape::Cylinder: o.object.shape = sim::ObjectShape::Cylinder; break;
    case scenario::Shape::Box: o.object.shape = sim::ObjectShape::Box; break;
    case scenario::Shape::Sphere: o.object.shape = sim::ObjectShape::Sphere; break;
  }
  o.object.size = sc.object.size;
  o.object.mass = sc.object.mass;
  const scenario::BodyDimensions body = scenario::bodyDimensionsFromHeight(sc.human.height);
  o.human.height = sc.human.height;
  o.human.upper_arm_length = body.upper_arm;
  o.human.forearm_length = body.forearm;
  return o;
}

control::ControllerConfig controllerConfigFor(const scenario::Scenario& sc) {
  return sc.config && !sc.config.IsNull() ? control::parseControllerConfig(YamlReader(sc.config, sc.config_path, ""))
                                          : control::loadControllerConfig(control::defaultControllerConfigPath());
}

}  // namespace

ExperimentRun runPaperExperiment(const scenario::Scenario& sc, ReachController which, const ExperimentOptions& opt) {
  if (sc.mode != scenario::Mode::HumanToRobot || !sc.human.holds_object)
    throw InputError(sc.file + ": the paper experiment needs mode human_to_robot with the person holding the object");
  const double duration = opt.duration.value_or(sc.duration);
  if (!(duration > 0.0) || !std::isfinite(duration))
    throw InputError("paper experiment: duration must be a positive number of seconds");

  // -- build everything once ------------------------------------------------
  const control::ControllerConfig cfg = controllerConfigFor(sc);
  control::Controller controller(control::loadModel(sourcePath("scenes/panda.urdf")), cfg);
  control::GraspOffset grasp;
  grasp.placement = sc.object.grasp;
  if (sc.object.free_axis >= 0) {
    grasp.has_free_axis = true;
    grasp.free_axis = control::Vector3::Unit(sc.object.free_axis);
  }
  controller.setGraspOffset(grasp);  // before reset(): it places the observed object at the TCP
  const bool method = which == ReachController::kMethod;
  if (!method) {
    // the baseline: a set point with the tracking task's own gains
    controller.poseTask().setGains(cfg.tracking.translation.gains, cfg.tracking.orientation.gains);
    controller.setTaskEnabled("tracking", false);
    controller.setTaskEnabled("pose", true);
  }

  sim::Simulation sim;
  sim.load(simOptionsFor(sc));
  human::ScriptedHuman person(sc);
  perception::SimulatedPoseSensor sensor(sc.sensor, static_cast<std::uint64_t>(sc.seed));
  const perception::PerceptionConfig pcfg = perception::loadPerceptionConfig(perception::defaultPerceptionConfigPath());
  perception::EstimatorSettings est_settings;
  est_settings.max_age = pcfg.max_age;
  est_settings.smoothing_time = pcfg.smoothing_time;
  est_settings.hand_T_object = *sc.human.holds_object;
  perception::PerceptionEstimator estimator(est_settings);

  // -- initial state: ready pose, object in the person's hand ---------------
  const control::Vector7 q0 = sc.robot.start_q.value_or(cfg.posture.target);
  sim.reset(q0, 0.08);
  {
    const human::HumanFacts facts =
        human::computeHumanFacts(sim.contacts(), sim.object(), sc.object, sc.human.start);
    const human::HumanOutput& out0 = person.step(0.0, facts);
    sim.setHumanPoses(out0.poses);
    sim.placeObject(out0.poses.hand * *sc.human.holds_object);
    sim.setObjectWeld(true);
  }
  control::ControlInputs cin;
  cin.q = q0;
  controller.reset(cin);

  const double dt = sim.timestep();
  const std::size_t steps = static_cast<std::size_t>(std::ceil(duration / dt)) + 1;
  ExperimentRun run;
  run.controller = which;
  run.samples.reserve(steps);
  ExperimentLog log;
  const int log_every = std::max(1, opt.log_every_ms);
  log.reserve(steps / static_cast<std::size_t>(log_every) + 2);
  const control::Model& model = controller.model();

  bool have_measurement = false;
  double last_stamp = -1.0;
  Eigen::Isometry3d measured = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d set_point = controller.tcpPose();
  const bool reference_mode = opt.execution == Execution::kJointReference;
  control::Vector7 q_ref = q0, qd_ref = control::Vector7::Zero();
  const auto wall0 = std::chrono::steady_clock::now();

  for (std::size_t k = 0; k < steps; ++k) {
    const double t = sim.time();

    // the person (reacts to physical facts only)
    const sim::ObjectState obj_true = sim.object();
    const sim::ContactReport contacts = sim.contacts();
    const human::HumanFacts facts = human::computeHumanFacts(contacts, obj_true, sc.object, sim.humanHandPose());
    const human::HumanOutput& hout = person.step(t, facts);
    sim.setHumanPoses(hout.poses);
    if (hout.holds_object != sim.objectWelded()) sim.setObjectWeld(hout.holds_object);

    // sensing and perception: the measured object pose (60 Hz, noisy)
    sensor.observe(t, hout.poses);
    estimator.update(t, sensor);
    const perception::PerceptionEstimate& est = estimator.estimate(t, perception::ObjectHolder::Person);
    const bool valid = est.object.valid && !est.object.stale;
    if (valid) {
      measured = est.object.pose;
      if (!have_measurement) controller.resetObservedObject(measured);  // start the observer on the data
      have_measurement = true;
      // the baseline's set point moves only when a new sample arrives
      if (est.human.stamp != last_stamp) {
        last_stamp = est.human.stamp;
        set_point = measured * sc.object.grasp;
        if (!method) controller.setPoseTarget(set_point);
      }
    }
    controller.setObservationTarget(measured, valid);

    // the QP, then torques to the simulator
    const sim::ArmState arm = sim.armState();
    cin.time = t;
    cin.q = reference_mode ? q_ref : arm.q;
    cin.qd = reference_mode ? qd_ref : arm.qd;
    control::Vector7 tau = controller.step(cin);
    if (reference_mode) {
      // the arm tracks the QP's own integrated joint state
      tau += opt.joint_stiffness.cwiseProduct(q_ref - arm.q) + opt.joint_damping.cwiseProduct(qd_ref - arm.qd);
      qd_ref += controller.lastQdd() * dt;  // semi-implicit Euler, as the controller's own integrator
      q_ref += qd_ref * dt;
    }
    sim::ArmCommand cmd;
    cmd.tau = tau;
    cmd.gripper_width = 0.08;  // the reaching phase: fingers stay open
    cmd.gripper_force = 40.0;
    sim.applyCommand(cmd);

    // what happened this step (ground truth from the simulator)
    ExperimentSample s;
    s.time = t;
    s.object_true = obj_true.pose;
    s.object_measured = measured;
    s.measured_valid = have_measurement;
    s.observed = controller.observedState().pose;
    s.reference = method ? controller.graspFrame().pose : set_point;
    s.grasp_true = obj_true.pose * sc.object.grasp;
    s.tcp = sim.tcpPose();
    s.hand_speed = hout.hand_speed;
    ExperimentArmRow row;
    row.q = arm.q;
    row.qd = arm.qd;
    row.tau = tau;
    for (int j = 0; j < 7; ++j) {
      s.position_violation |= arm.q[j] < model.q_min[j] - 1e-6 || arm.q[j] > model.q_max[j] + 1e-6;
      s.velocity_violation |= std::abs(arm.qd[j]) > model.v_max[j] + 1e-6;
      s.torque_violation |= !(std::abs(tau[j]) <= model.tau_max[j] + 1e-6);
      row.q_margin[j] = std::min(arm.q[j] - model.q_min[j], model.q_max[j] - arm.q[j]);
    }
    s.qp_failed = controller.lastStepFellBack();
    s.finger_on_object = contacts.left_finger_on_object || contacts.right_finger_on_object;
    s.robot_touches_person = contacts.robot_human > 0;
    run.samples.push_back(s);
    if (k % static_cast<std::size_t>(log_every) == 0) log.add(s, row);

    sim.step();
  }
  run.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  run.metrics = computeExperimentMetrics(run.samples, opt.thresholds);

  if (!opt.out_dir.empty()) {
    std::filesystem::create_directories(opt.out_dir);
    log.write(opt.out_dir + "/log.csv");
    const std::string json_path = opt.out_dir + "/metrics.json";
    std::ofstream(json_path) << metricsToJson(run.metrics, toString(which)) << "\n";
    if (opt.plots) {
      // Debian's python sees matplotlib; the one first on PATH may not
      const std::string cmd = "/usr/bin/python3 '" + sourcePath("scripts/plot_run.py") + "' '" + opt.out_dir + "'";
      if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "paper_experiment: plotting %s failed\n", opt.out_dir.c_str());
    }
  }
  return run;
}

namespace {
std::string num(const std::optional<double>& v, const char* fmt) {
  if (!v) return "-";
  char b[48];
  std::snprintf(b, sizeof b, fmt, *v);
  return b;
}
std::string num(double v, const char* fmt) { return num(std::optional<double>(v), fmt); }
std::string yesNo(const std::optional<bool>& b) { return b ? (*b ? "yes" : "no") : "-"; }
}  // namespace

std::string formatComparison(const ExperimentMetrics& a, const ExperimentMetrics& b) {
  std::ostringstream os;
  char line[200];
  auto row = [&](const char* name, const std::string& x, const std::string& y) {
    std::snprintf(line, sizeof line, "%-44s %14s %14s\n", name, x.c_str(), y.c_str());
    os << line;
  };
  row("metric", "method", "baseline");
  row("obs error vs true, pos RMS / max (mm)", num(a.obs_pos_vs_true.rms * 1e3, "%.2f") + " / " + num(a.obs_pos_vs_true.max * 1e3, "%.1f"),
      num(b.obs_pos_vs_true.rms * 1e3, "%.2f") + " / " + num(b.obs_pos_vs_true.max * 1e3, "%.1f"));
  row("obs error vs true, rot RMS / max (deg)", num(a.obs_rot_vs_true.rms, "%.2f") + " / " + num(a.obs_rot_vs_true.max, "%.1f"),
      num(b.obs_rot_vs_true.rms, "%.2f") + " / " + num(b.obs_rot_vs_true.max, "%.1f"));
  row("obs error vs measured, pos RMS / max (mm)", num(a.obs_pos_vs_measured.rms * 1e3, "%.2f") + " / " + num(a.obs_pos_vs_measured.max * 1e3, "%.1f"),
      num(b.obs_pos_vs_measured.rms * 1e3, "%.2f") + " / " + num(b.obs_pos_vs_measured.max * 1e3, "%.1f"));
  row("obs error vs measured, rot RMS / max (deg)", num(a.obs_rot_vs_measured.rms, "%.2f") + " / " + num(a.obs_rot_vs_measured.max, "%.1f"),
      num(b.obs_rot_vs_measured.rms, "%.2f") + " / " + num(b.obs_rot_vs_measured.max, "%.1f"));
  row("TCP vs its reference, pos RMS (mm)", num(a.track_pos.rms * 1e3, "%.1f"), num(b.track_pos.rms * 1e3, "%.1f"));
  row("TCP vs its reference, rot RMS (deg)", num(a.track_rot.rms, "%.2f"), num(b.track_rot.rms, "%.2f"));
  row("TCP vs true grasp, pos RMS (mm)", num(a.true_pos.rms * 1e3, "%.1f"), num(b.true_pos.rms * 1e3, "%.1f"));
  row("TCP vs true grasp, rot RMS (deg)", num(a.true_rot.rms, "%.2f"), num(b.true_rot.rms, "%.2f"));
  row("final error vs true grasp (mm)", num(a.final_pos_error * 1e3, "%.2f"), num(b.final_pos_error * 1e3, "%.2f"));
  row("final error vs true grasp (deg)", num(a.final_rot_error_deg, "%.2f"), num(b.final_rot_error_deg, "%.2f"));
  row("hand at rest from (s)", num(a.hand_rest_time, "%.3f"), num(b.hand_rest_time, "%.3f"));
  row("within 1 cm and 5 deg from (s)", num(a.reached_time, "%.3f"), num(b.reached_time, "%.3f"));
  row("hand at rest -> reached (s)", num(a.rest_to_reached, "%.3f"), num(b.rest_to_reached, "%.3f"));
  row("orientation within 5 deg from (s)", num(a.orientation_settle_time, "%.3f"), num(b.orientation_settle_time, "%.3f"));
  row("position within 1 cm from (s)", num(a.position_settle_time, "%.3f"), num(b.position_settle_time, "%.3f"));
  row("orientation converges first", yesNo(a.orientation_first), yesNo(b.orientation_first));
  row("limit violations pos/vel/torque (steps)",
      std::to_string(a.position_violations) + "/" + std::to_string(a.velocity_violations) + "/" + std::to_string(a.torque_violations),
      std::to_string(b.position_violations) + "/" + std::to_string(b.velocity_violations) + "/" + std::to_string(b.torque_violations));
  row("QP failures (steps)", std::to_string(a.qp_failures), std::to_string(b.qp_failures));
  row("finger-object / robot-person contact (steps)",
      std::to_string(a.finger_object_contact_steps) + "/" + std::to_string(a.person_contact_steps),
      std::to_string(b.finger_object_contact_steps) + "/" + std::to_string(b.person_contact_steps));
  return os.str();
}

}  // namespace handover::app
