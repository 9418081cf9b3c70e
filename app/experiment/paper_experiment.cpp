#include "app/experiment/paper_experiment.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/experiment/experiment_log.hpp"
#include "app/run/world_setup.hpp"
#include "config/input_error.hpp"
#include "control/controller.hpp"
#include "control/model/robot_description.hpp"
#include "fsm/handover/handover_fsm.hpp"
#include "fsm/handover/handover_params.hpp"
#include "perception/perception_config.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/simulated_pose_sensor.hpp"
#include "runtime/adapter/tracking_offset_rule.hpp"
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

const char* toString(GainSet g) { return g == GainSet::kPaper ? "paper" : "phase"; }

GainSet parseGainSet(const std::string& name) {
  if (name == "paper") return GainSet::kPaper;
  if (name == "phase") return GainSet::kHandoverPhase;
  throw InputError("unknown gain set '" + name + "' (expected paper or phase)");
}

std::pair<double, double> handoverPhaseStiffness() {
  const std::string path = fsm::HandoverFsm::defaultConfigPath();
  const fsm::HandoverParams p = fsm::loadHandoverParams(YamlReader::loadFile(path).child("params"));
  if (!(p.tracking_translation_stiffness > 0.0) || !(p.tracking_orientation_stiffness > 0.0))
    throw InputError(path + ": params.tracking must set translation_stiffness and orientation_stiffness > 0");
  return {p.tracking_translation_stiffness, p.tracking_orientation_stiffness};
}

control::GraspOffset preGraspOffset(const scenario::ObjectSpec& object, double standoff) {
  if (!(standoff >= 0.0) || !std::isfinite(standoff))
    throw InputError("paper experiment: standoff must be a finite distance >= 0 m");
  // the handover's own rule for an offset on the object (as the state machine's adapter applies it)
  const control::GraspOffset object_grasp = graspOffsetFor(object);  // placement and free axis
  return runtime::makeTrackingOffset(object_grasp.placement * Eigen::Translation3d(0.0, 0.0, -standoff), object_grasp,
                                 true);
}

namespace {

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
  control::Controller controller(control::loadModel(control::defaultRobotDescription(), control::Model{}.finger_opening), cfg);
  // the reach meets the pre-grasp frame (method: through the observed object)
  const control::GraspOffset target_offset = preGraspOffset(sc.object, opt.standoff);
  controller.setGraspOffset(target_offset);  // before reset(): it places the observed object at the TCP
  const bool method = which == ReachController::kMethod;
  control::PdGains k_trans = cfg.tracking.translation.gains, k_rot = cfg.tracking.orientation.gains;
  if (opt.gains == GainSet::kHandoverPhase) {
    const auto [kt, ko] = handoverPhaseStiffness();
    k_trans = control::PdGains::critical(kt);
    k_rot = control::PdGains::critical(ko);
  }
  if (method) {
    controller.trackingTask().setGains(k_trans, k_rot);
  } else {
    // the baseline: a set point with the tracking task's own gains
    controller.poseTask().setGains(k_trans, k_rot);
    controller.setTaskEnabled("tracking", false);
    controller.setTaskEnabled("pose", true);
  }

  sim::Simulation sim;
  sim.load(simOptionsFor(sc));
  human::ScriptedHuman person(sc);
  perception::SimulatedPoseSensor sensor(sc.sensor, static_cast<std::uint64_t>(sc.seed));
  const perception::PerceptionConfig pcfg = perception::loadPerceptionConfig(perception::defaultPerceptionConfigPath());
  perception::EstimatorSettings est_settings = pcfg.estimator;
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
  run.gains = opt.gains;
  run.translation_stiffness = k_trans.stiffness;
  run.orientation_stiffness = k_rot.stiffness;
  run.samples.reserve(steps);
  ExperimentLog log;
  const int log_every = std::max(1, opt.log_every_ms);
  log.reserve(steps / static_cast<std::size_t>(log_every) + 2);
  const control::Model& model = controller.model();
  // the target frame of a resting object pose, by the controller's own rule
  // (free axis, approach side, parallel-gripper twin picked by the wrist)
  const double wrist_mid = 0.5 * (model.q_min[6] + model.q_max[6]);
  auto targetFrame = [&](const Eigen::Isometry3d& object_pose, const Eigen::Matrix3d& R_tcp, double q_wrist) {
    control::ObservedState at_rest;
    at_rest.pose = object_pose;
    return control::graspFrameState(at_rest, control::Vector6::Zero(), target_offset, R_tcp, q_wrist - wrist_mid).pose;
  };

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
    const sim::ArmState arm = sim.armState();
    if (valid) {
      measured = est.object.pose;
      if (!have_measurement) controller.resetObservedObject(measured);  // start the observer on the data
      have_measurement = true;
      // the baseline's set point moves only when a new sample arrives
      if (est.human.stamp != last_stamp) {
        last_stamp = est.human.stamp;
        set_point = targetFrame(measured, controller.tcpPose().linear(), arm.q[6]);
        if (!method) controller.setPoseTarget(set_point);
      }
    }
    controller.setObservationTarget(measured, valid);

    // the QP, then torques to the simulator
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
    s.tcp = sim.tcpPose();
    s.grasp_true = targetFrame(obj_true.pose, s.tcp.linear(), arm.q[6]);
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
    if (sim.diverged()) throw std::runtime_error(sim.divergenceMessage());
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

std::string formatComparison(const std::vector<std::pair<std::string, ExperimentMetrics>>& runs) {
  std::ostringstream os;
  char cell[64];
  auto row = [&](const char* name, const auto& value_of) {
    std::snprintf(cell, sizeof cell, "%-46s", name);
    os << cell;
    for (const auto& [label, m] : runs) {
      std::snprintf(cell, sizeof cell, " %16s", value_of(m, label).c_str());
      os << cell;
    }
    os << "\n";
  };
  using M = ExperimentMetrics;
  using S = std::string;
  row("metric", [](const M&, const S& label) { return label; });
  row("obs error vs true, pos RMS / max (mm)", [](const M& m, const S&) {
    return num(m.obs_pos_vs_true.rms * 1e3, "%.2f") + " / " + num(m.obs_pos_vs_true.max * 1e3, "%.1f");
  });
  row("obs error vs true, rot RMS / max (deg)", [](const M& m, const S&) {
    return num(m.obs_rot_vs_true.rms, "%.2f") + " / " + num(m.obs_rot_vs_true.max, "%.1f");
  });
  row("obs error vs measured, pos RMS / max (mm)", [](const M& m, const S&) {
    return num(m.obs_pos_vs_measured.rms * 1e3, "%.2f") + " / " + num(m.obs_pos_vs_measured.max * 1e3, "%.1f");
  });
  row("obs error vs measured, rot RMS / max (deg)", [](const M& m, const S&) {
    return num(m.obs_rot_vs_measured.rms, "%.2f") + " / " + num(m.obs_rot_vs_measured.max, "%.1f");
  });
  row("TCP vs its reference, pos RMS (mm)", [](const M& m, const S&) { return num(m.track_pos.rms * 1e3, "%.1f"); });
  row("TCP vs its reference, rot RMS (deg)", [](const M& m, const S&) { return num(m.track_rot.rms, "%.2f"); });
  row("TCP vs true pre-grasp, pos RMS (mm)", [](const M& m, const S&) { return num(m.true_pos.rms * 1e3, "%.1f"); });
  row("TCP vs true pre-grasp, rot RMS (deg)", [](const M& m, const S&) { return num(m.true_rot.rms, "%.2f"); });
  row("final error vs true pre-grasp (mm)", [](const M& m, const S&) { return num(m.final_pos_error * 1e3, "%.2f"); });
  row("final error vs true pre-grasp (deg)", [](const M& m, const S&) { return num(m.final_rot_error_deg, "%.2f"); });
  row("hand at rest from (s)", [](const M& m, const S&) { return num(m.hand_rest_time, "%.3f"); });
  row("within 1 cm and 5 deg from (s)", [](const M& m, const S&) { return num(m.reached_time, "%.3f"); });
  row("hand at rest -> reached (s)", [](const M& m, const S&) { return num(m.rest_to_reached, "%.3f"); });
  row("orientation within 5 deg from (s)", [](const M& m, const S&) { return num(m.orientation_settle_time, "%.3f"); });
  row("position within 1 cm from (s)", [](const M& m, const S&) { return num(m.position_settle_time, "%.3f"); });
  row("orientation converges first", [](const M& m, const S&) { return yesNo(m.orientation_first); });
  row("limit violations pos/vel/torque (steps)", [](const M& m, const S&) {
    return std::to_string(m.position_violations) + "/" + std::to_string(m.velocity_violations) + "/" +
           std::to_string(m.torque_violations);
  });
  row("QP failures (steps)", [](const M& m, const S&) { return std::to_string(m.qp_failures); });
  row("finger-object / robot-person contact (steps)", [](const M& m, const S&) {
    return std::to_string(m.finger_object_contact_steps) + "/" + std::to_string(m.person_contact_steps);
  });
  return os.str();
}

}  // namespace handover::app
