#include "app/experiment/paper_experiment.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/experiment/experiment_log.hpp"
#include "app/joint_reference.hpp"
#include "app/run/world_setup.hpp"
#include "config/input_error.hpp"
#include "control/controller.hpp"
#include "fsm/handover/handover_fsm.hpp"
#include "fsm/handover/handover_params.hpp"
#include "perception/simulated_pose_sensor.hpp"
#include "runtime/adapter/tracking_offset_rule.hpp"
#include "runtime/handover_cycle.hpp"
#include "scenes/scenario/object_geometry.hpp"
#include "scenes/human/human_facts.hpp"
#include "scenes/human/scripted_human.hpp"
#include "scenes/sim/simulation.hpp"
#include "config/config_directory.hpp"

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

/// The reach's state table: config/fsm_reach.yaml (method) or
/// config/fsm_reach_baseline.yaml, with the standoff asked for.
YAML::Node reachTable(const std::string& path, double standoff) {
  YAML::Node doc = YamlReader::loadFile(path).node();
  YAML::Node reach = doc["machine"]["states"]["Reach"];
  if (!reach || !reach.IsMap()) throw InputError(path + ": expected a state machine.states.Reach");
  reach["standoff"] = standoff;
  return doc;
}

}  // namespace

ExperimentRun runPaperExperiment(const scenario::Scenario& sc, ReachController which, const ExperimentOptions& opt) {
  if (sc.mode != scenario::Mode::HumanToRobot || !sc.human.holds_object)
    throw InputError(sc.file + ": the paper experiment needs mode human_to_robot with the person holding the object");
  const double duration = opt.duration.value_or(sc.duration);
  if (!(duration > 0.0) || !std::isfinite(duration))
    throw InputError("paper experiment: duration must be a positive number of seconds");
  const bool method = which == ReachController::kMethod;
  // the reach meets the pre-grasp frame (the judge's rule below; the Reach state backs off the same)
  const control::GraspOffset target_offset = preGraspOffset(sc.object, opt.standoff);

  // -- the handover's control cycle, with the reach's state table -----------
  runtime::CycleSettings cs = runtime::defaultCycleSettings();
  cs.controller = controllerConfigFor(sc);
  // the paper's reach has no collision scene (docs/method.md): its entry is left out
  auto& constraints = cs.controller.constraints;
  constraints.erase(std::remove_if(constraints.begin(), constraints.end(),
                                   [](const control::ElementEntry& e) { return e.type == "collision"; }),
                    constraints.end());
  cs.collision_required = false;
  // the gains: the method's tracking task, and the baseline's set point with the tracking task's own
  control::PdGains k_trans = cs.controller.tracking.translation.gains, k_rot = cs.controller.tracking.orientation.gains;
  if (opt.gains == GainSet::kHandoverPhase) {
    const auto [kt, ko] = handoverPhaseStiffness();
    k_trans = control::PdGains::critical(kt);
    k_rot = control::PdGains::critical(ko);
  }
  if (method) {
    cs.controller.tracking.translation.gains = k_trans;
    cs.controller.tracking.orientation.gains = k_rot;
  } else {
    cs.controller.pose_task.translation.gains = k_trans;
    cs.controller.pose_task.orientation.gains = k_rot;
  }
  cs.fsm_config_path = configFile(method ? "fsm_reach.yaml" : "fsm_reach_baseline.yaml");
  cs.fsm_config = std::make_shared<const YAML::Node>(reachTable(cs.fsm_config_path, opt.standoff));
  cs.estimator.hand_T_object = *sc.human.holds_object;
  cs.object.mass = sc.object.mass;
  cs.object.grasp_in_object = sc.object.grasp;
  cs.object.com_in_tcp = sc.object.grasp.inverse().translation();
  cs.object.shape = scenario::primitiveShapeOf(sc.object);
  cs.object_grasp = graspOffsetFor(sc.object);
  runtime::HandoverCycle cycle(cs);
  const control::Controller& controller = cycle.controller();
  // the baseline's logged reference: its pose task's set point
  const int pose_index = controller.taskIndex("pose");
  const auto* pose_task =
      pose_index < 0 ? nullptr : dynamic_cast<const control::EndEffectorPoseTask*>(&controller.task(pose_index));
  if (!method && pose_task == nullptr) throw InputError(sc.file + ": the baseline needs a task named pose of type pose");

  sim::Simulation sim;
  sim.load(simOptionsFor(sc));
  human::ScriptedHuman person(sc);
  perception::SimulatedPoseSensor sensor(sc.sensor, static_cast<std::uint64_t>(sc.seed));

  // -- initial state: ready pose, object in the person's hand ---------------
  const control::Vector7 q0 = sc.robot.start_q.value_or(cs.controller.posture.target);
  sim.reset(q0, cs.gripper_open_width);
  {
    const human::HumanFacts facts =
        human::computeHumanFacts(sim.contacts(), sim.object(), sc.object, sc.human.start);
    const human::HumanOutput& out0 = person.step(0.0, facts);
    sim.setHumanPoses(out0.poses);
    sim.placeObject(out0.poses.hand * *sc.human.holds_object);
    sim.setObjectWeld(true);
  }
  {
    io::ArmState arm0;
    arm0.q = q0;
    cycle.start(arm0, false);
  }

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
  // the judge: the target frame of the TRUE object pose, by the controller's own rule
  // (free axis, approach side, parallel-gripper twin picked by the wrist)
  const double wrist_mid = 0.5 * (model.q_min[6] + model.q_max[6]);
  auto targetFrame = [&](const Eigen::Isometry3d& object_pose, const Eigen::Matrix3d& R_tcp, double q_wrist) {
    control::ObservedState at_rest;
    at_rest.pose = object_pose;
    return control::graspFrameState(at_rest, control::Vector6::Zero(), target_offset, R_tcp, q_wrist - wrist_mid).pose;
  };

  bool have_measurement = false;
  Eigen::Isometry3d measured = Eigen::Isometry3d::Identity();
  const bool reference_mode = opt.execution == Execution::kJointReference;
  JointReferenceExecution reference(q0, opt.joint_stiffness, opt.joint_damping);
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

    // the sensor sees the person (60 Hz, noisy); the arm reports its state
    sensor.observe(t, hout.poses);
    const io::ArmState arm = sim.state();

    // the control cycle: perception, the reach's state machine, QP
    cycle.plan();
    const io::ArmCommand& cycle_cmd = cycle.step(t, reference_mode ? reference.seen(arm) : arm, sensor);
    const io::ArmCommand cmd =
        reference_mode ? reference.command(cycle_cmd, arm, controller.lastQdd(), dt) : cycle_cmd;
    sim.apply(cmd);

    // what happened this step (ground truth from the simulator)
    const perception::PerceptionEstimate& est = cycle.estimate();
    if (est.object.valid && !est.object.stale) {
      measured = est.object.pose;
      have_measurement = true;
    }
    ExperimentSample s;
    s.time = t;
    s.object_true = obj_true.pose;
    s.object_measured = measured;
    s.measured_valid = have_measurement;
    s.observed = controller.observedState().pose;
    s.reference = method ? controller.graspFrame().pose : pose_task->target();
    s.tcp = sim.tcpPose();
    s.grasp_true = targetFrame(obj_true.pose, s.tcp.linear(), arm.q[6]);
    s.hand_speed = hout.hand_speed;
    ExperimentArmRow row;
    row.q = arm.q;
    row.qd = arm.qd;
    row.tau = cmd.tau;
    for (int j = 0; j < 7; ++j) {
      s.position_violation |= arm.q[j] < model.q_min[j] - 1e-6 || arm.q[j] > model.q_max[j] + 1e-6;
      s.velocity_violation |= std::abs(arm.qd[j]) > model.v_max[j] + 1e-6;
      s.torque_violation |= !(std::abs(cmd.tau[j]) <= model.tau_max[j] + 1e-6);
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
  cycle.stop();
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
