// Settings shared by the handover states (`params:` in config/fsm.yaml).
// Thresholds that belong to one state live in that state's definition.
// Loaded and validated at start-up (not RT safe); read-only afterwards.
#pragma once

#include "config/yaml_reader.hpp"
#include "fsm/handover/controller_interface.hpp"

namespace handover::fsm {

/// Where the robot may meet the person: inside a sphere AND a box (world).
struct Workspace {
  Vector3 center = Vector3(0.0, 0.0, 0.333);  ///< m, sphere centre (near the shoulder joint)
  double radius = 0.85;                        ///< m
  Vector3 box_min = Vector3(0.15, -0.6, -0.1); ///< m
  Vector3 box_max = Vector3(1.0, 0.6, 0.9);    ///< m
  /// Inside both, each grown by `margin` (m; the sphere's radius, the box's faces).
  bool contains(const Vector3& p, double margin = 0.0) const;
};

struct HandoverParams {
  Workspace workspace;
  double reach_radius = 0.75;        ///< m from workspace.center: a settled object/hand closer is "within reach"
  int max_retries = 2;               ///< retries after an abort before giving up
  /// Tracking-task stiffness (1/s^2, critically damped) while the robot
  /// follows the person (approach, grasp, present); 0 = the controller's
  /// configured gains (the paper's K = 1 / 2 in config/controller.yaml).
  double tracking_translation_stiffness = 0.0;
  double tracking_orientation_stiffness = 0.0;
  /// The same while the fingers line up on the object in the person's hand
  /// (Grasp); 0 = the gains above. Stiffer: the fingers must line up within
  /// the object's clearance (6-9 mm), and a PD's steady error under the
  /// model's small errors shrinks as 1/K. Not while approaching: a stiff
  /// approach meets an object the person still brings in hard enough to
  /// strike it.
  double align_tracking_translation_stiffness = 0.0;
  double align_tracking_orientation_stiffness = 0.0;
  /// m/s, the fastest the aligning fingers close in on the object (0 = the
  /// tracking task's own limit): stiff gains converge sooner, and a
  /// fingertip that lands on a misjudged object lands no faster than this.
  double align_tracking_max_speed = 0.0;
  /// The same once the fingers close (Grasp, after the close command): the
  /// object the person holds centres the closing fingers, so the arm must
  /// give way to them; held stiffly against them the wrist was spun past its
  /// speed limit. Not configured: the align gains; 0: the gains as they are.
  double closing_tracking_translation_stiffness = 0.0;
  double closing_tracking_orientation_stiffness = 0.0;
  /// The follow gains once the tracked body has arrived: at rest the
  /// tracking stiffens to these, and eases back to the follow gains as the
  /// body's speed rises to arrive_speed (linear between). The soft follow
  /// gains are for a body still on its way (a stiff arm would meet it hard,
  /// and would rush at a person it may lose sight of); once the person has
  /// brought it in, nothing is gained by converging slowly. 0 = off.
  double arrive_tracking_translation_stiffness = 0.0;
  double arrive_tracking_orientation_stiffness = 0.0;
  double arrive_speed = 0.0;  ///< m/s
  /// A take's own arrive gains and speed (the object at rest in the giver's
  /// hand), where they differ from a give's (a receiver's open hand, which a
  /// stiff gripper presses into). 0 = the arrive gains above.
  double take_arrive_tracking_translation_stiffness = 0.0;
  double take_arrive_tracking_orientation_stiffness = 0.0;
  double take_arrive_speed = 0.0;  ///< m/s
  /// A take's approach goes where the person's reach will end (the object's
  /// rest pose, HandoverInput::object.rest_pose), holds its grasp choice once
  /// that is known, and starts once it lies in the workspace. Off: where the
  /// object is (docs/state-machine.md, "Meeting the reach where it ends").
  bool anticipate_reach = false;
  // gripper
  double gripper_open_width = 0.08;  ///< m, commanded opening
  double gripper_close_width = 0.0;  ///< m, commanded when grasping (the object stops the fingers)
  double gripper_force = 40.0;       ///< N, force limit while opening (and before a grasp)
  /// m/s: how fast the gap between the fingers closes (0: not known). A close
  /// meets the object (gap - object width) / closing_speed later: Grasp
  /// closes when the TCP will be at the grasp then.
  double gripper_closing_speed = 0.0;
  /// m: fingers closed nearer than this hold nothing (a grasp on nothing is
  /// missed; fingers that close so far while waiting for a release lost the
  /// object to the person)
  double gripper_empty_width = 0.004;
  /// m: half the size of a finger's contact face, across and along the
  /// fingers: the lever by which a turn of the gripper against the object
  /// widens the object's footprint between the fingers (grasp_funnel.hpp)
  double finger_half_span = 0.012;
  /// m: how far the finger pads reach past the TCP along the approach axis
  /// (the Panda's: 9.5 mm)
  double finger_pad_reach = 0.0095;
  /// m: how deep the pads must reach into the object when they meet it for
  /// Grasp to close (half the grasp's own depth where that is less;
  /// grasp_funnel.hpp deepEnough)
  double grip_depth = 0.006;
  /// The grip on the object (gripper.grip): each finger presses with F, and
  /// friction holds 2 mu F against the object's weight and the retract's
  /// accelerations, F >= margin m (g + acceleration) / (2 mu); and each pad's
  /// torsional friction (mu_t F, N m) holds the moment of that weight about
  /// the fingers' closing axis (TCP y), F >= margin m (g + acceleration) d /
  /// (2 mu_t), d the centre of mass's distance from that axis (a baton held
  /// 10 cm off its centre needs twice the force of one held at its centre).
  /// The larger, clipped to [min_force, max_force].
  double grip_friction = 0.5;        ///< mu, finger-object friction coefficient assumed
  double grip_torsional_friction = 0.01;  ///< mu_t, m: torque per newton of normal force at one pad
  double grip_margin = 2.0;          ///< safety factor on the friction force
  double grip_acceleration = 3.0;    ///< m/s^2 the held object may see beyond gravity
  double grip_min_force = 10.0;      ///< N
  double grip_max_force = 70.0;      ///< N, the gripper's continuous force
  /// Grasp force (N) for an object of `mass` kg whose centre of mass sits at
  /// `com_in_tcp` (m, TCP frame). RT safe.
  double gripForce(double mass, const Vector3& com_in_tcp) const;
  // wrist force-torque sensor
  double ft_filter_tau = 0.05;       ///< s, low-pass time constant of the world-frame force
  /// Change of the world z force reading per unit of hanging weight: -1 when
  /// a held mass m lowers the reading by m g (force the hand exerts on the
  /// flange, as the simulator reports), +1 for the opposite convention.
  double ft_gravity_sign = -1.0;
  double gravity = 9.81;             ///< m/s^2
  // perception and withdrawal
  double max_data_age = 0.1;         ///< s, older samples are not used to start an approach
  double stale_timeout = 0.5;        ///< s without a sample during an approach = the person withdrew
  double withdraw_speed = 0.3;       ///< m/s away from workspace.center (or toward home) = leaving
  /// m a leaving motion must carry the body for a withdrawal (WithdrawalWatch; 0: any)
  double withdraw_distance = 0.0;
  /// m: the workspace grows by this for the withdrawal test (not for the offer): a hand resting
  /// on the region's edge went out and in with every noisy sample, withdrawn and offered again
  double withdraw_workspace_margin = 0.0;
  /// m: the body back within this of where it was first seen (the person's rest place), having
  /// been twice this from it since the watch restarted, is withdrawn however slowly it went (0: off)
  double withdraw_home_radius = 0.0;
  /// s: how far the body has gone from where it was first seen counts low-passed by this
  /// (HandoverContext::*_farthest_from_home; 0: as estimated)
  double away_time_constant = 0.0;
  /// N: a pull beyond the object's weight toward where the person's hand came from, while
  /// the fingers close on or hold the object they still carry = they take it back (0: never)
  double take_back_force = 0.0;
  // poses (TCP in the world)
  Isometry stow_pose = Isometry::Identity();   ///< where a taken object is carried
  Isometry safe_pose = Isometry::Identity();   ///< where the robot retreats after an abort
  Isometry ready_pose = Isometry::Identity();  ///< where an object to give is held
  /// Desired object pose in the person's hand frame when presenting.
  Isometry object_in_hand = Isometry::Identity();
  /// m: a given object is lowered in the hand until its lowest point is at
  /// most this far above the grip point (seated_in_hand.hpp; 0: as placed).
  double object_in_hand_seat = 0.0;
  /// The open gripper rides along with an object the receiver takes out of
  /// it, across the approach axis, until it is clear of the fingers
  /// (release_ride.hpp); false: it holds its place.
  bool release_ride = false;
  /// Timed carries and lift-offs (timed_move.hpp): the peak joint speed of a
  /// carry's joint-space move (rad/s) and the shortest move (s); the held
  /// object's acceleration is bounded by grip_acceleration. 0 speed: the
  /// moves are set-point steps closed by the tasks' own gains.
  double carry_joint_speed = 0.0;
  double carry_joint_acceleration = 4.0;  ///< rad/s^2, the carry's ramps' peak
  double carry_min_duration = 0.3;
};

/// Reads and validates `params`; throws InputError naming file, key, line.
HandoverParams loadHandoverParams(const YamlReader& params);
/// {pos: [x, y, z], rpy: [r, p, y]} (m, rad) to a pose.
Isometry readPose(const YamlReader& node);

}  // namespace handover::fsm
