// Plain inputs of the handover state machine, filled once per control cycle
// by the application (from the simulator or a robot driver, perception and
// the controller). Frames: world (z up, base at origin) unless stated; SI
// units; spatial velocities are [linear; angular] in world axes.
#pragma once

#include "fsm/handover/grasp_plan.hpp"
#include "interfaces/object_shape.hpp"

namespace handover::fsm {

/// A body seen by perception (the person's hand or the object).
struct SensedBody {
  Isometry pose = Isometry::Identity();  ///< body frame in the world (hand: grip point)
  Vector6 velocity = Vector6::Zero();    ///< estimated [linear (m/s); angular (rad/s)]
  /// m/s, standard deviation of each component of the linear velocity estimate (0: taken as
  /// exact): a track a few samples old knows little of its speed
  double speed_std = 0.0;
  bool valid = false;                    ///< a sample has been received and is usable
  double age = 1e9;                      ///< s since the last sample (stale data grows this)
  double stamp = -1.0;                   ///< s, measurement time of the latest sample (-1: none); a new sample changes it
  /// Where the body will come to rest: the end of the person's reach as far as it is
  /// predicted (perception/reach_predictor.hpp), `pose` when no reach is under way;
  /// only when `rest_known` (restPose()).
  Isometry rest_pose = Isometry::Identity();
  bool rest_known = false;
};

/// Where `b` will come to rest, as far as known (else where it is).
inline const Isometry& restPose(const SensedBody& b) { return b.rest_known ? b.rest_pose : b.pose; }

struct HandoverInput {
  double time = 0.0;  ///< s since the start of the run

  // arm
  Vector7 q = Vector7::Zero();              ///< joint positions, rad
  Vector7 qd = Vector7::Zero();             ///< joint velocities, rad/s
  /// rad: the smallest distance of a joint to its position limit (the model's)
  double joint_limit_margin = 1e9;
  Isometry tcp_pose = Isometry::Identity(); ///< tool centre point in the world
  Vector6 tcp_velocity = Vector6::Zero();   ///< TCP [linear; angular], world axes
  double finger_width = 0.0;                ///< total finger opening, m

  /// Wrist F/T sensor [force (N); torque (N m)] in the sensor frame, as
  /// io::ArmState::wrench reports it.
  Vector6 wrench = Vector6::Zero();
  /// Rotation of the F/T sensor frame in the world (from the kinematics), so
  /// the force can be compared with gravity.
  Eigen::Matrix3d ft_rotation = Eigen::Matrix3d::Identity();
  /// Share of the object's weight the robot carries, 0..1 (control::
  /// ContactWrenchEstimator, one cycle old): 0 while the person holds it.
  double load_share = 0.0;
  /// Force on the gripper beyond the tool and the held object's own weight
  /// and inertia, world axes, N (ContactWrenchEstimator::interactionForce,
  /// one cycle old): what the person adds. A pull reads here, not the arm's
  /// braking with the object.
  Vector3 interaction_force = Vector3::Zero();
  /// What touches the gripper beyond the tool (ContactWrenchEstimator::load,
  /// one cycle old): [force (N); torque (N m) about the TCP], world axes.
  /// With the fingers open it is the contact of a finger or the palm on the
  /// object: where along the closing axis it pushes tells which finger.
  Vector6 tool_contact = Vector6::Zero();

  // perception
  SensedBody hand;          ///< the person's hand (grip point frame, design notes 1)
  SensedBody object;        ///< the object
  bool hand_open = true;    ///< the hand is empty and open (ready to receive)
  /// Smallest distance between the robot links and the person's arm and
  /// hand, m (fingers excluded while they share the object). Large if unknown.
  double human_distance = 1e9;
  /// The same split by body: robot to the person's forearm and upper arm
  /// (never a grasp-zone exception), and robot to the hand (closeness is the
  /// point inside the grasp zone). Large if unknown: then human_distance
  /// alone decides, with the grasp-zone exception.
  double arm_distance = 1e9;
  double hand_distance = 1e9;
  /// A collision row with the person is engaged (some robot-person pair is
  /// inside its interaction distance): the constraint, not the tasks, decides
  /// how near the arm goes. One cycle old, like the distances.
  bool person_constraint_engaged = false;

  // controller feedback
  ObservationTarget observed_target = ObservationTarget::kNone;  ///< what the observation follows now
  Isometry observed_pose = Isometry::Identity();   ///< observed frame (virtual object)
  Vector6 observed_velocity = Vector6::Zero();
  /// The tracking target frame in the world (grasp frame or presentation
  /// frame = observed pose * tracking offset) and its velocity.
  Isometry target_pose = Isometry::Identity();
  Vector6 target_velocity = Vector6::Zero();
  bool holds_object = false;  ///< the controller believes the gripper holds the object

  // grasp planning (the planner's latest choices; invalid without a planner)
  TrackingPlan object_plan;  ///< grasp frame in the object frame (take)
  TrackingPlan hand_plan;    ///< TCP in the receiver's hand frame (give)
};

/// What the task knows about the object (from the scenario), set once.
struct ObjectInfo {
  double mass = 0.3;                          ///< kg
  Vector3 com_in_tcp = Vector3::Zero();       ///< centre of mass in the TCP frame when grasped, m
  Isometry grasp_in_object = Isometry::Identity();  ///< grasp frame in the object frame
  /// Its primitive shape (object frame): the grasp funnel reads how it fits
  /// between the fingers. Unknown: the gripper slides straight in.
  io::ObjectShape shape;
};

/// Counters and the outcome, readable by the application every cycle.
struct HandoverStats {
  const char* outcome = "running";  ///< running | success | aborted | failed
  int handovers = 0;                ///< completed handovers
  int aborts = 0;                   ///< attempts abandoned (person withdrew, no release, no pull, ...)
  int retries = 0;                  ///< attempts begun after an abort (the person came back)
  int safety_stops = 0;             ///< preemptions by the safety stop
  int bad_input_cycles = 0;         ///< cycles with non-finite sensor values (ignored)
};

}  // namespace handover::fsm
