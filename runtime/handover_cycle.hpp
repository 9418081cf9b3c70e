// One control cycle of the handover product (1 ms): the arm's state and the
// person's pose samples in, one arm command out. Everything that turns
// sensing into a command lives here, so the simulated run, a real-arm driver
// loop, the paper experiment, `handover hold`, the benchmark and the tests
// all call the same function; what differs between them is the state table
// (settings.fsm_config_path: config/fsm.yaml, fsm_reach*.yaml, fsm_hold.yaml):
//
//   HandoverCycle cycle(settings);          // not RT safe: loads, allocates
//   cycle.start(arm.state(), holds_object); // once, before the first step
//   every 1 ms:
//     driver.apply(cycle.step(t, driver.state(), pose_source));
//   cycle.stop();                           // tears down the active states
//
// Stages of step(t, arm, source), in this order:
//   0. plan        (plan(), before step, not timed with it) grasp or
//                  presentation choice from the previous cycle's estimate;
//                  the answer to a carry request a state posted in the
//                  previous step (the held object's upright placement).
//   1. perceive    drain `source` of the samples that arrived by t; the
//                  estimate at t (hand, forearm, upper arm, object). Who holds
//                  the object is the payload the state machine set in the
//                  previous cycle; while the robot holds it, its pose is the
//                  TCP pose of the previous Controller::step with the grasp
//                  the state machine closed on.
//   2. velocities  hand and object velocities: the estimator's motion model's
//                  (kalman), else finite differences on new samples.
//   3. fsm input   assemble fsm::HandoverInput (table below).
//   4. fsm         the state machine steps; through the adapter it changes
//                  set-points (tasks, targets, gains, gripper, payload) that
//                  take effect in stage 7 of this same cycle.
//   5. target      the observation target from this cycle's estimate
//                  (blending between object and hand as selected in stage 4).
//   6. collision   the collision constraint's person capsules from this
//                  cycle's estimate (skipped without a collision constraint,
//                  settings.collision_required false).
//   6b. contact    the wrist wrench of `arm` (ContactWrenchEstimator, at the
//                  previous step's sensor rotation and acceleration): the
//                  load share scales the object's payload in the model, and
//                  the rest of the load is the controller's known external
//                  wrench (config/controller.yaml contact_wrench).
//   7. QP          Controller::step(q, qd of `arm`): kinematics, tasks,
//                  constraints, solve, torques; updates the TCP pose, the
//                  observed object and the collision distances.
//   8. command     torques from 7, gripper width and force from 4.
//
// Age of every input of the state machine (stage 3), relative to `arm`:
//   this cycle          q, qd, finger width, wrist wrench (from `arm`);
//                       the hand and object estimates (each sample itself is
//                       `age` s old: sensor rate and latency);
//   one cycle old       TCP pose and velocity, F/T sensor rotation, load
//                       share (stage 6b of the previous cycle), observed
//                       object pose and velocity, tracking target frame,
//                       robot-person distances: all computed by the previous
//                       Controller::step at the previous q (before the first
//                       step: from start()'s reset at the start state);
//   as last commanded   observation target kind, object held (payload set);
//   as last planned     object_plan, hand_plan, the carry answer (stage 0).
//
// Frames: world (z up, robot base at the origin); SI units.
// Real-time: step() allocates nothing and does no I/O (the controller's QP
// fallback is counted, not printed: see control::Controller). Construction,
// start() and stop() are not RT safe.
#pragma once

#include <memory>
#include <string>

#include <yaml-cpp/yaml.h>

#include "control/collision/collision_config.hpp"
#include "control/constraints/collision_constraint.hpp"
#include "control/controller.hpp"
#include "control/controller_config.hpp"
#include "control/model/robot_description.hpp"
#include "control/wrench/contact_wrench.hpp"
#include "fsm/handover/handover_fsm.hpp"
#include "interfaces/arm_io.hpp"
#include "perception/observation_target.hpp"
#include "perception/perception_estimator.hpp"
#include "perception/pose_source.hpp"
#include "perception/reach_predictor.hpp"
#include "runtime/adapter/controller_adapter.hpp"
#include "runtime/grasp_planning.hpp"
#include "runtime/sensed_velocity.hpp"

namespace handover::runtime {

/// Everything the cycle is built from (start-up only).
struct CycleSettings {
  control::RobotDescription robot;            ///< the robot's model: URDF + names, roles, limits
  control::ControllerConfig controller;       ///< tasks, constraints, gains (config/controller.yaml)
  /// The task and constraint types config/controller.yaml's entries may name
  /// (control/controller_registry.hpp); add a type here before constructing the cycle.
  control::ControllerRegistry registry = control::ControllerRegistry::shipped();
  control::CollisionConfig collision;         ///< collision pairs (config/collision.yaml)
  /// The state table the cycle runs (config/fsm.yaml: the handover; the
  /// paper's reach and `hold` run their own, config/fsm_reach*.yaml,
  /// config/fsm_hold.yaml, with the same states' mechanism).
  std::string fsm_config_path;
  /// The controller config must have a constraint of type collision (the
  /// handover's safety reads the robot-person distances); false allows a
  /// config without one (the paper's reach, negative controls): stage 6 is
  /// then skipped and the state machine reads the person 2 m away.
  bool collision_required = true;
  /// The state table as a parsed document, read instead of the file when set
  /// (a caller that adjusts a state's key, e.g. the reach's standoff);
  /// fsm_config_path then names it in messages. Held by pointer, as
  /// control::ElementEntry::node (a YAML::Node assignment rebinds).
  std::shared_ptr<const YAML::Node> fsm_config;
  perception::EstimatorSettings estimator;    ///< incl. the object's pose in the person's hand
  perception::ObservationTargetSettings target;
  perception::ReachPredictorSettings reach_prediction;  ///< where the person's reach will end
  fsm::ObjectInfo object;                     ///< mass, grasp frame in the object, CoM in the TCP when held
  control::GraspOffset object_grasp;          ///< grasp frame in the object frame, with its symmetry
  double gripper_open_width = 0.08;           ///< m, widest opening (config/fsm.yaml params.gripper)
  double gripper_force = 40.0;                ///< N, grasp force limit at start (params.gripper)
  double forearm_length = 0.27;               ///< m, the person's forearm capsule (collision)
  double upper_arm_length = 0.33;             ///< m, the person's upper-arm capsule (collision)
  /// Where the person stands, as declared (scenario `human.stand`): trackers
  /// report the hand, forearm and upper arm only, so the trunk (legs, torso,
  /// head; sized by controller collision.person.trunk) is placed from the
  /// tracked shoulder (the upper arm's origin) and this facing. Without a
  /// declared stand the trunk is not in the collision scene.
  struct PersonStand {
    bool declared = false;
    double yaw = 3.14159265358979;  ///< rad about z; pi faces the robot from +x
    /// m, the tracked shoulder sideways from the body midline, toward the
    /// person's right (+) or left (-): +shoulder_offset for a right hand
    double shoulder_side = 0.175;
  } stand;
  /// params.ft.gravity_sign: -1 when io::ArmState::wrench is what the hand
  /// exerts on the flange (the simulator), +1 for the opposite convention.
  double ft_gravity_sign = -1.0;
  /// Grasp planning (config/grasp_selection.yaml): the grasps the object
  /// admits; empty = no planner (the declared grasp, named poses).
  control::grasp::GraspSelectionConfig grasp_selection;
  std::vector<control::grasp::GraspSpec> object_grasps;
};

/// CycleSettings from the repository's config files (config/*.yaml, the
/// robot description config/robot.yaml and its URDF); the object and person fields keep their defaults
/// for the caller to fill. Throws handover::InputError.
CycleSettings defaultCycleSettings();

class HandoverCycle {
 public:
  /// Loads the model and the state machine; throws handover::InputError.
  explicit HandoverCycle(const CycleSettings& settings);
  HandoverCycle(const HandoverCycle&) = delete;
  HandoverCycle& operator=(const HandoverCycle&) = delete;

  /// Initial gripper command (closed on the object when `holds_object`,
  /// with its payload; else open) and the controller's reset at `arm`
  /// (velocities taken as zero). Call once before the first step.
  void start(const io::ArmState& arm, bool holds_object);

  /// The planning stage, outside the 1 ms step: re-selects the grasp (take)
  /// or the presentation (give) when perception has a new sample since the
  /// last call, from the last step's estimate and q, and answers the carry
  /// request a state posted in the last step (upright placement of the held
  /// object, HandoverFsm::plan). Call it once per cycle before step() (it
  /// returns at once without a new sample or a request), or from a slower
  /// thread on a real robot (then hand over the plans and the carry channel
  /// under a lock). No allocation; 0.1-1 ms per new sample, about 1.5 ms per
  /// carry request, one when Retract, HoldReady or Retreat starts with the
  /// object in the gripper (docs/performance.md).
  void plan();

  /// One cycle at time `t` (s): stages 1-8 above. The reference stays valid
  /// until the next call. RT safe.
  const io::ArmCommand& step(double t, const io::ArmState& arm, perception::PoseSource& source);

  /// Tears down the active states (end of a run).
  void stop() { machine_->stop(); }

  /// The QP's tasks and constraints (built from settings.controller's
  /// entries through settings.registry; docs/architecture.md). Not RT safe.
  control::Formulation& formulation() { return controller_.formulation(); }

  // --- read-outs of the last cycle (for logs, judges, tests) ---------------
  const io::ArmCommand& command() const { return command_; }
  const perception::PerceptionEstimate& estimate() const { return *estimate_; }
  /// Pose samples the estimator refused so far (its plausibility gates).
  long rejectedSamples() const { return estimator_.rejected(); }
  /// The same per reason.
  const perception::RejectCounts& rejects() const { return estimator_.rejects(); }
  /// The source tracks the object as its own body (not hand * offset).
  bool objectTracked() const { return estimator_.objectTracked(); }
  const perception::TargetOutput& target() const { return obs_target_.output(); }
  const fsm::HandoverInput& fsmInput() const { return input_; }
  const fsm::HandoverFsm& machine() const { return *machine_; }
  const control::Controller& controller() const { return controller_; }
  const ControllerAdapter& adapter() const { return adapter_; }
  /// The state machine's controller interface, to drive it directly (tests, tools).
  ControllerAdapter& adapter() { return adapter_; }
  /// The grasp planner (null without object grasps).
  const GraspPlanning* planning() const { return planning_.get(); }
  /// The collision constraint (config/controller.yaml's entry of type
  /// collision); absent only with settings.collision_required false.
  /// collision() requires hasCollision().
  bool hasCollision() const { return collision_ != nullptr; }
  const control::CollisionConstraint& collision() const { return *collision_; }
  /// Index of the person-hand/gripper rule the state machine relaxes (-1: none).
  int handGripperRule() const { return hand_rule_; }
  /// The wrist load, load share and feed-forward of the last cycle (stage 6b).
  const control::ContactWrenchEstimator& contactWrench() const { return contact_; }
  /// Hand and object velocities from perception, [linear; angular] world axes.
  const Eigen::Matrix<double, 6, 1>& handVelocity() const { return hand_vel_.velocity(); }

 private:
  void assembleInput(double t, const io::ArmState& arm, const perception::PerceptionEstimate& est);

  CycleSettings settings_;
  control::Controller controller_;
  std::shared_ptr<control::CollisionConstraint> collision_;
  int hand_rule_ = -1;
  int ft_frame_ = -1;
  perception::PerceptionEstimator estimator_;
  perception::ObservationTarget obs_target_;
  perception::ReachPredictor reach_;  ///< fed in plan(): where the person's hand will rest
  bool robot_held_ = false;           ///< the robot held the object last step (payload set)
  bool predict_reach_ = false;        ///< the state machine anticipates reaches (params.tracking.anticipate_reach)
  /// A collision rule keeps the arm from where the reach will end (the
  /// human_hand_forecast body): reach_ is fitted for it too.
  bool forecast_hand_ = false;
  /// This cycle's estimate with the hand and the object where the reach will
  /// end (as far as reach_ trusts it); read instead of the estimate while
  /// the state machine anticipates (observation target, grasp planning).
  perception::PerceptionEstimate led_;
  ControllerAdapter adapter_;
  std::unique_ptr<fsm::HandoverFsm> machine_;
  std::unique_ptr<GraspPlanning> planning_;
  SensedVelocity hand_vel_, object_vel_;
  /// The person's forearm and upper arm, differenced from their estimated poses
  /// (the collision dampers read how fast they come at the arm).
  SensedVelocity forearm_vel_, upper_arm_vel_;
  perception::PerceptionEstimate no_estimate_;  ///< before the first step
  const perception::PerceptionEstimate* estimate_ = &no_estimate_;
  fsm::HandoverInput input_;
  control::ContactWrenchEstimator contact_;
  control::ControlInputs control_in_;
  io::ArmCommand command_;
};

}  // namespace handover::runtime
