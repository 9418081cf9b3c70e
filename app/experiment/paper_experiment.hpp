// The paper's experiment (section III) in simulation, without the handover's
// phases: the scripted person brings the object to a place the controller
// is not told; the arm reaches for it from the ready pose with one of two
// controllers, and the run is logged and measured (experiment_metrics.hpp).
// It runs the handover's own control cycle (runtime::HandoverCycle::step:
// perception, state machine, QP) with a one-state table of its own:
//
//   kMethod:   config/fsm_reach.yaml, Reach {follow: tracking}: observation
//              task -> pre-grasp frame (rigid-body relations) ->
//              trajectory-tracking task, coupled inside one QP (the frame's
//              acceleration is a function of the QP's alphadot_obs),
//              tracking on from t = 0.
//   kBaseline: config/fsm_reach_baseline.yaml, Reach {follow: set_point}: a
//              set-point end-effector pose task ("pose") toward the latest
//              MEASURED pre-grasp pose (measured object pose * offset,
//              updated when a 60 Hz sample arrives, no feed-forward),
//              tracking task off, same stiffness/damping as the tracking task.
//
// The reach meets the PRE-GRASP frame, as the handover's Approach state does:
// the grasp frame backed off along its own z axis (the gripper's approach
// axis) by `standoff`, so the open fingers never sweep over the object; the
// experiment is the paper's reaching phase (no closing) and every "reached"
// metric is measured against the TRUE pre-grasp frame (true object pose *
// the same offset, chosen by the same rule for a symmetric object).
//
// Per 1 ms step (as app/run/run_scenario.cpp, sharing its
// app/run/world_setup.hpp): person -> simulator -> pose sensor ->
// HandoverCycle::step -> simulator; the loop here only runs the simulator,
// the scripted person, the sensor and the judge. Both controllers use the
// scenario's controller config (or config/controller.yaml) without its
// collision constraint (the paper's reach has no collision scene), and the
// perception settings of config/perception.yaml. The observation task runs in
// both (it only feeds the arm in kMethod); its state is logged for both. The
// joint-reference execution stays on the driver side (app/joint_reference.hpp).
// Not real-time safe as a whole (it builds everything, then allocates nothing
// per step except the reserved traces).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "app/experiment/experiment_metrics.hpp"
#include "control/tasks/grasp_frame.hpp"
#include "scenes/scenario/scenario.hpp"

namespace handover::app {

enum class ReachController { kMethod, kBaseline };
const char* toString(ReachController c);
/// "method" | "baseline"; throws InputError otherwise.
ReachController parseReachController(const std::string& name);

/// How the QP's joint accelerations reach the simulated arm.
///  kTorque:         tau = M(q) qddot + h(q, qdot) on the measured state (inverse dynamics only).
///  kJointReference: as the paper's experiment (mc_rtc on a Panda): the QP
///                   runs on its own integrated joint state (q_ref, qdot_ref),
///                   and a joint impedance tau = M qddot + h + Kp (q_ref - q) +
///                   Kd (qdot_ref - qdot) makes the arm track it, so model
///                   errors between the controller and MuJoCo do not bias the
///                   soft task-space gains.
enum class Execution { kTorque, kJointReference };
const char* toString(Execution e);
/// "torque" | "reference"; throws InputError otherwise.
Execution parseExecution(const std::string& name);

/// Stiffness (1/s^2, critically damped) of the tracking task (method) and of
/// the set point (baseline).
///  kPaper:         config/controller.yaml's tracking gains (the paper's K = 1 / 2).
///  kHandoverPhase: config/fsm.yaml's params.tracking (the handover's approach phase).
enum class GainSet { kPaper, kHandoverPhase };
const char* toString(GainSet g);
/// "paper" | "phase"; throws InputError otherwise.
GainSet parseGainSet(const std::string& name);

/// Translation and orientation stiffness of config/fsm.yaml params.tracking
/// (InputError if the file is bad or either is not set).
std::pair<double, double> handoverPhaseStiffness();

/// The tracking offset of the reach, in the object frame: the scenario's
/// grasp backed off by `standoff` (m) along the grasp z axis, with the
/// handover's rules for an empty gripper (controller_adapter.cpp): the
/// object's free axis if it has one, approach from the robot's base (world
/// origin) and the parallel-gripper half-turn twin.
control::GraspOffset preGraspOffset(const scenario::ObjectSpec& object, double standoff);

struct ExperimentOptions {
  Execution execution = Execution::kTorque;
  /// Joint impedance of kJointReference, N m/rad and N m s/rad (the Panda's
  /// usual joint-impedance example gains).
  Eigen::Matrix<double, 7, 1> joint_stiffness = (Eigen::Matrix<double, 7, 1>() << 600, 600, 600, 600, 250, 150, 50).finished();
  Eigen::Matrix<double, 7, 1> joint_damping = (Eigen::Matrix<double, 7, 1>() << 50, 50, 50, 20, 20, 20, 10).finished();
  std::string out_dir;               ///< log.csv, metrics.json and plots go here; "" = write nothing
  bool plots = true;                 ///< run scripts/plot_run.py on out_dir
  int log_every_ms = 5;              ///< log.csv row period (metrics use every step)
  std::optional<double> duration;    ///< s simulated; default: the scenario's duration
  double standoff = 0.08;            ///< m, pre-grasp back-off along the grasp z (config/fsm.yaml Approach)
  GainSet gains = GainSet::kPaper;
  MetricThresholds thresholds;
};

struct ExperimentRun {
  ReachController controller = ReachController::kMethod;
  GainSet gains = GainSet::kPaper;
  double translation_stiffness = 0.0;  ///< 1/s^2, as run
  double orientation_stiffness = 0.0;
  ExperimentMetrics metrics;
  std::vector<ExperimentSample> samples;  ///< every control step
  double wall_time = 0.0;                 ///< s
};

/// Runs one controller on the scenario (human_to_robot, person holding the
/// object; InputError otherwise or for bad files) and, with out_dir, writes
/// out_dir/log.csv, out_dir/metrics.json and (plots) the PNGs.
ExperimentRun runPaperExperiment(const scenario::Scenario& scenario, ReachController controller,
                                 const ExperimentOptions& options);

/// Runs side by side (one column per named run), one line per metric.
std::string formatComparison(const std::vector<std::pair<std::string, ExperimentMetrics>>& runs);

}  // namespace handover::app
