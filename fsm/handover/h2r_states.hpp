// Human to robot: the person offers the object, the robot takes it.
#pragma once

#include <cmath>

#include "fsm/handover/grasp_funnel.hpp"
#include "fsm/handover/handover_state.hpp"
#include "fsm/handover/receiver_take.hpp"
#include "fsm/handover/rest_window.hpp"
#include "fsm/handover/stall_recovery.hpp"
#include "fsm/handover/take_back.hpp"
#include "fsm/handover/withdrawal_watch.hpp"

namespace handover::fsm {

/// [Offered] (WaitForOffer) / [ReceiverComing] (WaitForReceiver). Holds the
/// TCP still and observes the object (or hand) until it is inside the
/// workspace and either comes toward the robot faster than approach_speed,
/// or rests (moves less than settle_speed * settle_time over settle_time:
/// rest_window.hpp) within reach: within params.reach_radius, or farther
/// where the grasp planner's inverse kinematics reaches it (a valid plan for
/// the object or the hand) once it has left the place it was first seen (a
/// person at the table's side holds the object out 0.81 m from the shoulder,
/// in the arm's reach, and was waited for until they gave up).
/// WaitForReceiver also needs HandoverInput::hand_open. With home_radius
/// (m, optional; after an abort) a rest within that distance of where the
/// body was first seen (the person's rest place, HandoverContext::home_*)
/// is the person back at rest, not an offer: only coming toward the robot is;
/// with home_rest_time (s, >= settle_time) such a rest is an offer once it
/// lasted that long (a person who holds the object out where they were
/// first seen, and waits). With withdrawn_at_home: true, the body seen back
/// within home_radius of there after it had been out of that circle
/// (HandoverContext::*_farthest_from_home, low-passed) is the person back at rest:
/// [Withdrawn] at once, in the workspace or not (counted as an abort, coming
/// back is a retry). Coming is faster than approach_speed by
/// approach_significance (default 0) standard deviations of the velocity
/// estimate (SensedBody::speed_std).
/// With carried_in_distance (m, optional), a body within reach that is still
/// moving (faster than approach_speed, as significant), not away from the
/// robot, and that far from where it was first seen is coming too: brought
/// in from the side, it crosses the robot's front more than it comes nearer.
/// Keys: approach_speed, settle_speed (m/s), settle_time (s), home_radius (m),
/// home_rest_time (s), withdrawn_at_home, approach_significance,
/// carried_in_distance (m).
class WaitForPerson : public HandoverState {
 public:
  explicit WaitForPerson(bool hand);
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  /// The person came (back): after an abort, that begins a retry.
  static void cameBack(HandoverContext& ctx);

  bool hand_;
  int out_, pulled_ = -1, withdrawn_ = -1;
  ReceiverTake take_;  ///< a give: a receiver who takes the object the robot waits with
  double approach_speed_ = 0.1, settle_speed_ = 0.05, settle_time_ = 0.3;
  double home_radius_ = 0.0;  ///< m, 0: a rest anywhere within reach counts
  double home_rest_time_ = 0.0;  ///< s, a rest at home that long is an offer (0: never)
  double significance_ = 0.0;    ///< standard deviations of the speed estimate coming must exceed
  double carried_in_ = 0.0;      ///< m from home, moving within reach, not away: coming (0: off)
  RestWindow rest_;  ///< the body resting within reach
};

/// [Near, Withdrawn] Observation on the object (or hand), tracking the grasp
/// (or presentation) frame. The object approach opens the gripper.
/// Blind, it holds: while the tracked body's data is older than
/// params.max_data_age (a dropout), the TCP holds where it is instead of
/// heading for a prediction of a person it cannot see; tracking resumes with
/// the next fresh sample (a person gone for good ends as Withdrawn). Near
/// also needs the body to have arrived (slower than params.arrive_speed,
/// when set): the stiff phase after it is for a body at rest. Tracking
/// gains follow the body's speed (setPhaseGainsForSpeed).
/// A take with funnel_margin approaches continuously: the standoff is the
/// grasp funnel's (grasp_funnel.hpp) once the object has arrived (slower
/// than params.arrive_speed; the full standoff while it is still brought
/// in, and after every switch of the planned grasp), with the TCP's offset
/// from the approach line along the fingers' width counted against the fit
/// too (the slide goes along the line), so the fingers slide in as the
/// alignment converges instead of stopping at the pre-grasp pose first. In
/// the funnel the hand clearance is relaxed as in Grasp (the fingers go
/// around the object the person holds). Near is then near the funnel's
/// current target.
/// Keys: near_distance (m, TCP to target frame); standoff (m, the pre-grasp
/// distance along the approach axis) with, for a take's funnel,
/// standoff_speed (m/s), standoff_feed_forward (bool, default false: the
/// slide's rate fed forward to the tracking, GraspFunnel) with
/// standoff_acceleration (m/s^2, optional: a smooth slide),
/// funnel_margin (share of the clearance, 0..1) and motion_horizon (s,
/// optional, default 0: off) with motion_significance (standard deviations):
/// the object's motion within the horizon costs the fit and, toward the
/// palm, adds a lead to the standoff (budgetMotion);
/// a give's lift (m, optional, default 0: none) with lift_speed (m/s): the
/// presentation is approached from above the receiver's hand;
/// a take's yield_force (N, optional, default 0: off): the empty gripper
/// pushed harder than that has struck something (the object or the hand is
/// not where the sensor says): the rest of the approach tracks at the soft
/// follow gains, not the stiff arrive gains that pressed on into it;
/// stall_time (s, optional): an approach to a target at rest that makes no
/// progress for that long with a joint at its limit goes on in joint space
/// to the planner's configuration (stall_recovery.hpp)
/// (presentation_descent.hpp).
class Approach : public HandoverState {
 public:
  explicit Approach(bool hand);
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  /// A take's funnel: the standoff toward the funnel's, once the object has
  /// `arrived`; after a stall beside the object (StallRecovery::detouring),
  /// lined up as far back again as the TCP is off the approach line. True
  /// when the gripper stands beside the object (past the funnel's mouth, more
  /// than near_distance off the approach line). RT safe.
  bool slideIn(HandoverContext& ctx, bool arrived);

  bool hand_;
  int near_, withdrawn_, pulled_ = -1;
  ReceiverTake take_;  ///< a give: a receiver who takes the object on its way to them
  StallRecovery stall_;  ///< stall_time: a stalled approach goes on in joint space, or around the object
  WithdrawalWatch withdrawal_;  ///< the person leaves: Withdrawn
  double near_distance_ = 0.1;
  double near_orientation_ = M_PI;  ///< rad
  double standoff_ = 0.0;           ///< m, pre-grasp distance along the approach axis
  double lift_ = 0.0;               ///< m, most the give's target is raised over the hand
  double lift_speed_ = 0.4;         ///< m/s, fastest change of the lift
  double last_time_ = 0.0;          ///< s, the last cycle (the lift's rate)
  bool blind_ = false;              ///< holding: the tracked body's data is stale
  double yield_force_ = 0.0;        ///< N on the empty gripper that is a strike (0: off)
  bool struck_ = false;             ///< struck: the follow gains for the rest of the approach
  GraspFunnel funnel_;              ///< a take's continuous approach; max_standoff 0: none
};

/// [Grasped, Missed, Withdrawn] Keeps tracking the grasp frame; closes when
/// the position and orientation errors are within tolerance now and where the
/// TCP will be when the fingers meet the object (params.gripper.closing_speed:
/// the fingers take (clearance x 2) / closing_speed; alignedWhenClosed),
/// recording the force before the grasp. A close waited for the TCP to come
/// to rest before (a speed tolerance): 0.15 s of every take's last
/// centimetres, while the fingers need as long to get there. Once closing for at least
/// confirm_time and the fingers have stopped (slower than stall_speed), the
/// grasp is confirmed by a finger width above params.gripper.empty_width (not closed on
/// nothing), else missed. Withdrawn: before closing, the person withdrew
/// (withdrawn()); before closing and while closing, they take the object back
/// (TakeBack for touch_time: through the open fingers, it pushes one toward
/// them, or the way their hand goes: TakeBack::carried).
/// Slides in through the grasp funnel (grasp_funnel.hpp): backed off by up
/// to `standoff` along the approach axis while the object does not fit
/// between the open fingers, all the way in once it does; it closes only
/// with the object between the fingers.
/// Felt, not only seen: a fingertip that lands on the object (the pose
/// sensor off by more than the fingers' clearance) pushes the gripper back
/// along its approach axis, and the wrist wrench's torque about the TCP tells
/// which finger it is. The object then lies farther toward that finger than
/// the sensor says: the grasp is corrected by the clearance toward it (the
/// middle of what can be off while one finger still lands), the funnel backs
/// the fingers off and slides them in again. Not more than max_touches times
/// per attempt.
/// Keys: position_tolerance (m), orientation_tolerance_deg, confirm_time (s),
/// stall_speed (m/s), standoff (m,
/// optional, default 0: no funnel) with standoff_speed (m/s),
/// standoff_feed_forward (bool, default false: the slide fed forward, and
/// ended at the grasp also once closing) with standoff_acceleration (m/s^2,
/// optional: a smooth slide that goes on from the approach's) and
/// funnel_margin (share of the clearance, 0..1), motion_horizon and
/// motion_significance (as Approach's); touch_force (N, optional,
/// default 0: no correction) with touch_time (s) and max_touches; jam_force
/// (N, optional, default 0: off) with jam_time (s): the open gripper pushed
/// back that hard for that long is jammed against the object (it struck the
/// palm or the fingers' base, no correction frees it): Missed, the gripper
/// backs off open instead of pressing on into it.
/// Felt again once closed: the width the fingers stopped at locates them on
/// the object's section (depthOfWidth). Narrower than the object is at its
/// hold depth (FingerFit::hold_depth), they pinch a round side short of it
/// (a bottle lying across them, seen 3 cm off by a calibration error, rolled
/// out of a 5.0 cm pinch of its 6.6 cm): while the person still holds the
/// object (their hand has not moved from it by release_distance), the
/// fingers open, the grasp moves along the approach axis by as much as the
/// pads fell short, and they close again. Not once the weight is coming over
/// (the robot's load share at least regrip_max_share): the person lets go
/// before their hand moves, and opening then dropped the object they had just
/// let go of (g1097_00316: the share 0.61, the hand still). regrips
/// (optional, default 0) times per attempt; release_distance (m, default
/// 0.015); regrip_max_share (0..1, default 1: any share).
class Grasp : public HandoverState {
 public:
  Grasp();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  FingerFit fitNow(const HandoverContext& ctx) const;
  /// s the fingers take from the close to the object for fit `f`. RT safe.
  double closingTime(const HandoverContext& ctx, const FingerFit& f) const;
  /// The grasp frame corrected by what the fingers felt (world).
  Isometry correctedGraspFrame(const HandoverContext& ctx) const;
  /// The observed object moved as that correction moved the grasp (world).
  Isometry correctedObject(const HandoverContext& ctx) const;
  /// A fingertip on the object: corrects the grasp toward it; true when it
  /// did. `f`: the fit before. RT safe.
  bool feelTouch(HandoverContext& ctx, const FingerFit& f);
  /// The open gripper pushed back along its approach axis by at least
  /// jam_force for jam_time. RT safe.
  bool jammed(const HandoverContext& ctx);
  /// Closed short of the object's hold depth while the person still holds it:
  /// opens and moves the grasp in by the shortfall; true when it did. RT safe.
  bool regrip(HandoverContext& ctx);

  int grasped_, missed_, withdrawn_;
  mutable HoldDepthCache hold_depth_;  ///< the object's hold depth for the grasp now (fitNow): one scan per grasp
  double pos_tol_ = 0.01, rot_tol_ = 0.17, confirm_time_ = 0.3;
  double stall_speed_ = 0.01;
  GraspFunnel funnel_;           ///< max_standoff 0: no funnel
  bool closing_ = false;
  double closed_at_ = 0.0;
  double last_width_ = 0.0, last_time_ = 0.0, finger_speed_ = 0.0;
  double touch_force_ = 0.0;     ///< N, push along the approach axis that is a touch (0: off)
  double touch_time_ = 0.05;     ///< s, for this long
  int max_touches_ = 2;
  int touches_ = 0;
  double touch_since_ = -1.0;    ///< s, the push began; < 0: none
  bool touch_felt_ = false;      ///< this push was answered (waits for it to end)
  double jam_force_ = 0.0;       ///< N, push along the approach axis that is a jam (0: off)
  double jam_time_ = 0.2;        ///< s, for this long
  double jam_since_ = -1.0;      ///< s, the jam's push began; < 0: none
  Vector3 touch_shift_ = Vector3::Zero();  ///< m, the grasp's correction, object frame
  int max_regrips_ = 0;
  int regrips_ = 0;
  double release_distance_ = 0.015;  ///< m the hand moves off the object when it lets go
  double regrip_max_share_ = 1.0;    ///< load share from which the person is letting go: no regrip
  bool reopening_ = false;           ///< a regrip: the fingers open before the grasp moves in
  Vector3 regrip_shift_ = Vector3::Zero();  ///< m, object frame, applied once they are open
  Vector3 hand_at_close_ = Vector3::Zero(); ///< m, world: the hand when the fingers closed (it stays: it holds on)
  bool hand_at_close_known_ = false;
  TakeBack pull_;                ///< before and while closing (restarted at the close)
  TakeBack carried_;             ///< before closing: the open fingers carried along (TakeBack::carried)
  WithdrawalWatch withdrawal_;   ///< before closing: the person leaves
};

/// [Released, Withdrawn] Follows, then holds, the grasp pose until the person lets go, for
/// hold_time: the robot's load share (HandoverInput::load_share) reaches
/// release_share and the person's hand has moved release_distance from where
/// it held the object, measured in the TCP's frame (a stale hand: the share
/// alone; a hand that stays: the share alone once it held for release_wait),
/// or, without release_share, the filtered world force has gained at least
/// release_fraction * m g along gravity since the grasp. Then sets the
/// payload (the robot holds the object). Withdrawn: the person takes the
/// object back (TakeBack for hold_time; whatever the load share says, which
/// a pull down and away raises): the fingers let them have it.
/// Why both: while the person's grip is rigid the load on the wrist is
/// whatever the robot pushes (the load share follows the robot's own
/// payload), so the load alone cannot tell that the person let go; the hand
/// leaving can. Leaving in any direction: a hand that still grips the object
/// the gripper holds cannot move against it. Counted as a distance from the
/// TCP that grows, a hand whose way home passed beside and over the gripper
/// (a person standing to its side, resting higher than they offered) came
/// nearer it while it left, and the robot opened its fingers on the object it
/// carried when the state timed out (g479_00803).
/// While the person holds the object the TCP follows it (its estimate moves
/// with their hand: no force builds against a hand that still moves; held
/// still from the start, a hand rising 2 cm as the fingers closed was pushed
/// on with 10 N, and the object fell 2.4 cm when they let go). From the first
/// moment the robot bears most of the load (load share >= hold_share, at most
/// release_share; below half of hold_share it follows again) the TCP is
/// held still, not following the estimate (it still moves with the person's
/// leaving hand until the release is confirmed, and dragged the object down
/// with it), at the stiffness the grasp aligned with (params.tracking.align):
/// at the pose task's K = 6 (times the arm's task-space inertia: tens of
/// N/m) half a newton the model missed as the weight came over sank the
/// object by 2-3 cm.
/// Nothing left between the fingers (they closed to below
/// params.gripper.empty_width, what tells Grasp a grasp on nothing: a person who took the object
/// back as the fingers closed, the pull not felt): Withdrawn as well. Waiting
/// on, the robot held its closed fingers where the person's hand came back to
/// offer it again (struck, g409_00790); the interrupt object_lost watches
/// only once the robot carries the object (payload set). Not a narrowing of
/// the grip alone: an object that turns in the fingers as the person lets go
/// narrows it too, and opening then dropped it (g1_00060).
/// The person takes it back (params.withdraw.take_back_force, for hold_time):
/// pulled toward where their hand came from across the floor, or along the way
/// their hand goes once it moves (more than motion_significance standard
/// deviations of its speed estimate) back toward where it was first seen
/// (goingHome: one who moves the object on to where they hand it over pulls it
/// along their way too, outsider m_24): Withdrawn, the fingers open.
/// Keys: release_share (0..1) with release_distance (m), release_wait
/// (s) and hold_share (0.05..release_share, default release_share), or
/// release_fraction (0..2); hold_time (s); motion_significance (default 2).
class WaitForRelease : public HandoverState {
 public:
  WaitForRelease();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  int released_, withdrawn_;
  TakeBack pull_;
  TakeBack carried_;            ///< the pull along the way the person's hand goes (TakeBack::carried)
  double significance_ = 2.0;   ///< motion_significance: standard deviations of the hand's speed that are noise
  double fraction_ = 0.7, hold_time_ = 0.1;
  double share_ = -1.0;  ///< release_share; < 0: the force rule
  double hold_share_ = 1.0;  ///< hold_share (<= release_share): the load share from which the TCP is held still
  bool holding_ = false; ///< the robot carries the load: holding the TCP still (stiffly), not following
  /// Holds the TCP where it is, as stiffly as the grasp aligned it.
  void hold(HandoverContext& ctx);
  double distance_ = 0.0;   ///< release_distance, m
  double wait_ = 3.5;       ///< release_wait, s
  double carry_since_ = -1.0;  ///< s, since when the robot carries the load
  bool hand_started_ = false;  ///< hand_start_ is set
  Vector3 hand_start_ = Vector3::Zero();  ///< m, the hand in the TCP's frame when first seen in this state
  Vector3 hand_start_world_ = Vector3::Zero();  ///< m, the hand minus the TCP (world axes) then
  double since_ = -1.0;
};

}  // namespace handover::fsm
