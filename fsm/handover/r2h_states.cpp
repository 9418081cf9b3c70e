#include "fsm/handover/r2h_states.hpp"

#include <cmath>
#include <limits>

#include "fsm/handover/perception_checks.hpp"
#include "fsm/handover/presentation_descent.hpp"
#include "fsm/handover/tracking_setup.hpp"

namespace handover::fsm {

HoldReady::HoldReady() : ready_(declareOutput("Ready")) {}

void HoldReady::configure(const YamlReader& def) {
  pos_tol_ = readPositive(def, "position_tolerance", 0.5);
  settle_speed_ = readPositive(def, "settle_speed", 1.0);
  if (def.has("blocked_time")) blocked_time_ = readRange(def, "blocked_time", 0.0, 10.0);
  if (def.has("wait_for_person")) wait_for_person_ = readRange(def, "wait_for_person", 0.0, 5.0);
  if (take_.configure(def)) pulled_ = declareOutput("Pulled");
}

void HoldReady::onStart(HandoverContext& ctx) {
  const HandoverParams& p = *ctx.params;
  blocked_since_ = -1.0;
  take_.restart();
  ctrl().setGripper(p.gripper_close_width, p.gripForce(ctx.object.mass, ctx.comInTcp()));  // keep the grip
  if (!ctx.ledger->payloadSet()) ctrl().setPayload(ctx.object.mass, ctx.comInTcp());
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(ObservationTarget::kHand);
  started_ = ctx.time;
  carrying_ = false;
  ctrl().setPoseTarget(p.ready_pose);
  if (ctx.in.hand.valid) startCarry(ctx);
}

void HoldReady::startCarry(HandoverContext& ctx) {
  // the receiver's hand stops at the object's side: half its widest
  // horizontal extent, upright the way it is to be presented
  const Vector3 up = presentedUpAxis(ctx);
  double half_width = 0.0;
  for (int k = 0; k < 3; ++k)
    if (std::abs(up[k]) < 0.5) half_width = std::max(half_width, 0.5 * io::extentAlong(ctx.object.shape, Vector3::Unit(k)));
  constexpr double kUnknownShape = 0.01;  // m: still reached for, its size unknown
  carry_.start(ctx, ctrl(), ctx.params->ready_pose, up, std::max(half_width, kUnknownShape));
  carrying_ = true;
}

bool HoldReady::onRun(HandoverContext& ctx) {
  if (take_.taken(ctx)) {
    setOutput(pulled_);
    return true;
  }
  if (!carrying_) {
    if (!ctx.in.hand.valid && ctx.time - started_ < wait_for_person_) return false;
    startCarry(ctx);
  }
  carry_.update(ctx, ctrl());
  const bool settled = ctx.in.tcp_velocity.head<3>().norm() <= settle_speed_;
  // a receiver already reaching in holds the arm off its carry pose (the
  // collision constraint stops it beside them; the arm jitters there, as the
  // person's sensed pose does, so no settling test): the ready pose is only
  // where to wait for them, and they are here, so waiting there is over
  const bool blocked = !carry_.waiting() && blocked_time_ >= 0.0 && ctx.in.person_constraint_engaged;
  if (!blocked) {
    blocked_since_ = -1.0;
  } else if (blocked_since_ < 0.0) {
    blocked_since_ = ctx.time;
  }
  if (blocked && ctx.time - blocked_since_ >= blocked_time_) {
    setOutput(ready_);
    return true;
  }
  if (carry_.waiting() || positionError(ctx.in.tcp_pose, carry_.goal()) > pos_tol_ || !settled) return false;
  setOutput(ready_);
  return true;
}

void HoldReady::onTeardown(HandoverContext& ctx) { carry_.stop(ctx); }

Present::Present()
    : presented_(declareOutput("Presented")), withdrawn_(declareOutput("Withdrawn")), pulled_(declareOutput("Pulled")) {}

void Present::configure(const YamlReader& def) {
  pos_tol_ = readPositive(def, "position_tolerance", 0.2);
  rot_tol_ = readPositive(def, "orientation_tolerance_deg", 180.0) * M_PI / 180.0;
  speed_tol_ = readPositive(def, "speed_tolerance", 2.0);
  settle_time_ = readRange(def, "settle_time", 0.0, 5.0);
  if (def.has("pull_threshold")) pull_threshold_ = readPositive(def, "pull_threshold", 100.0);
  if (def.has("pull_hold_time")) pull_hold_ = readRange(def, "pull_hold_time", 0.0, 5.0);
  if (def.has("lift_speed")) lift_speed_ = readPositive(def, "lift_speed", 2.0);
}

void Present::onStart(HandoverContext& ctx) {
  rest_.reset();
  keeps_.reset();
  withdrawal_.restart();
  pull_since_ = -1.0;
  last_time_ = ctx.time;
  ctx.force_holding = ctx.force;  // the object's and hand's weight, as carried in
  ctx.interaction_holding = ctx.interaction;
  // the descent the approach began goes on from where it is
  trackTarget(ctx, ctrl(), true, 0.0, TrackingGains::kFollow, ctx.tracking_shift);
}

bool Present::onRun(HandoverContext& ctx) {
  setPhaseGainsForSpeed(*ctx.params, ctrl(), TrackingGains::kFollow, ctx.in.hand.velocity.head<3>().norm());
  settleDescent(ctx, ctrl(), lift_speed_, ctx.time - last_time_);
  last_time_ = ctx.time;
  // a person who takes hold and pulls before the robot settled: that is the
  // handover, and the hand moving away is the pull, not a withdrawal
  if (pull_threshold_ > 0.0 && (ctx.interaction - ctx.interaction_holding).norm() > pull_threshold_ &&
      receiverMayHoldIt(ctx)) {
    if (pull_since_ < 0.0) pull_since_ = ctx.time;
    if (ctx.time - pull_since_ >= pull_hold_) {
      setOutput(pulled_);
      return true;
    }
  } else {
    pull_since_ = -1.0;
  }
  if (withdrawal_.withdrawn(ctx, true)) {
    setOutput(withdrawn_);
    return true;
  }
  // the receiver takes the object, not the gripper: its pose up to its symmetry counts
  HandoverInput at = ctx.in;  // against the presentation itself, not the raised target
  at.target_pose = trackedGraspFrame(ctx);
  // settled on displacements over the window, not on speeds: the target follows the hand's
  // estimate, and a 30 Hz, 1 cm tracker's jittered it (and the arm following it) at 0.1-0.3 m/s
  // around a hand at rest; the jitter averages out over the window. The TCP keeps its place
  // against the target, and the receiver's hand rests (rest_window.hpp: DetectPull holds still,
  // and held still against a hand still moving at 0.1-0.2 m/s the object was pushed along with
  // it, 2 cm before anything counted as a pull)
  if (!presentedAtTarget(at, ctx.object, pos_tol_, rot_tol_, std::numeric_limits<double>::infinity())) {
    rest_.reset();
    keeps_.reset();
    return false;
  }
  const Vector3 against = ctx.in.tcp_pose.translation() - at.target_pose.translation();
  const bool keeps = keeps_.rests(against, ctx.time, speed_tol_, settle_time_);  // both windows fed every cycle
  const bool rests = rest_.rests(ctx.in.hand.pose.translation(), ctx.time, speed_tol_, settle_time_);
  if (!keeps || !rests) return false;
  setOutput(presented_);
  return true;
}

DetectPull::DetectPull() : pulled_(declareOutput("Pulled")) {}

void DetectPull::configure(const YamlReader& def) {
  threshold_ = readPositive(def, "pull_threshold", 100.0);
  hold_time_ = readRange(def, "hold_time", 0.0, 5.0);
  if (def.has("moved_time")) {
    moved_time_ = readPositive(def, "moved_time", 10.0);
    if (def.has("rest_speed")) rest_speed_ = readPositive(def, "rest_speed", 1.0);
    moved_ = declareOutput("Moved");
  }
  if (auto s = def.optionalChild("stiff_hold")) stiff_hold_ = s->asBool();
}

void DetectPull::onStart(HandoverContext& ctx) {
  ctrl().relaxHandClearance(true);  // the hand and the gripper share the object now
  since_ = -1.0;
  ctx.force_holding = ctx.force;  // removes the object's (and hand's) weight from the test
  ctx.interaction_holding = ctx.interaction;  // and a hand resting on it
  moved_since_ = -1.0;
  hand_rest_.reset();
  hand_seen_at_start_ = fresh(ctx.in.hand, ctx.params->max_data_age);
  hand_at_start_ = ctx.in.hand.pose.translation();
  ctrl().enableTracking(false);
  // hold still so a pull builds force - where the object was to be
  // presented: Present accepts a TCP short of it by up to its tolerance,
  // and the last centimetres are what put the object in the hand
  ctrl().setPoseTarget(trackedGraspFrame(ctx));
  // stiff_hold: as Release holds. While the receiver's hand is near, the load is no longer
  // compensated (contact_wrench, disturbance: `carry`), and at the pose task's own gains a tube held
  // from the side turned joint 7 by 1 rad in 2.5 s and swept the fingers into the palm resting under
  // it (g1051_00727; the shipped scenario r2h_hand_rests_under, 595 contact steps). A pull builds its
  // force sooner
  if (stiff_hold_) holdAtClosingGains(*ctx.params, ctrl());
}

bool DetectPull::onRun(HandoverContext& ctx) {
  if (moved_ >= 0 && handMoved(ctx)) {
    setOutput(moved_);
    return true;
  }
  if ((ctx.interaction - ctx.interaction_holding).norm() <= threshold_ || !receiverMayHoldIt(ctx)) {
    since_ = -1.0;
    return false;
  }
  if (since_ < 0.0) since_ = ctx.time;
  if (ctx.time - since_ < hold_time_) return false;
  setOutput(pulled_);
  return true;
}

bool DetectPull::handMoved(HandoverContext& ctx) {
  constexpr double kMoved = kReceiverGripReach;  // m: farther, the grip left where the object was put for it
  const bool seen = fresh(ctx.in.hand, ctx.params->max_data_age);
  if (seen && !hand_seen_at_start_) {  // first seen now: from here
    hand_seen_at_start_ = true;
    hand_at_start_ = ctx.in.hand.pose.translation();
  }
  const Vector3 hand = ctx.in.hand.pose.translation();
  // at rest again somewhere new: near the object or not, a hand that would hold it had pulled
  const bool rests = seen && hand_rest_.rests(hand, ctx.time, rest_speed_, moved_time_);
  const bool away = seen && (hand - hand_at_start_).norm() > kMoved && (!receiverMayHoldIt(ctx) || rests);
  if (!away) {
    moved_since_ = -1.0;
    return false;
  }
  if (moved_since_ < 0.0) moved_since_ = ctx.time;
  return ctx.time - moved_since_ >= moved_time_;
}

Release::Release() : opened_(declareOutput("Opened")) {}

void Release::configure(const YamlReader& def) { min_width_ = readRange(def, "min_width", 0.0, 0.08); }

void Release::onStart(HandoverContext& ctx) {
  ctrl().relaxHandClearance(true);  // the hand and the gripper share the object now
  ctrl().setGripper(ctx.params->gripper_open_width, ctx.params->gripper_force);
  ctrl().enableTracking(false);
  hold_ = ctx.in.tcp_pose;
  ride_.start(ctx);
  ctrl().setPoseTarget(hold_);
  // held as stiffly as closing fingers are (a take's WaitForRelease too): at
  // the pose task's own K = 6, meant for retracts, the arm drifted 3 mm on
  // with the pull it had given way to, and the finger nearest the palm met it
  // as it opened (g787_00457). Only while the fingers open: stiff on in
  // ConfirmGone, the gripper stood in the way of a cylinder pulled out at
  // 0.6 m/s and the blow spun joint 6 past its limit (g823_00417)
  holdAtClosingGains(*ctx.params, ctrl());
}

bool Release::onRun(HandoverContext& ctx) {
  ride_.hold(ctrl(), hold_, ctx.in);
  if (ctx.in.finger_width < min_width_) return false;
  setOutput(opened_);
  return true;
}

ConfirmGone::ConfirmGone() : gone_(declareOutput("Gone")) {}

void ConfirmGone::configure(const YamlReader& def) {
  min_width_ = readRange(def, "min_width", 0.0, 0.08);
  fraction_ = readPositive(def, "gone_fraction", 2.0);
  hold_time_ = readRange(def, "hold_time", 0.0, 5.0);
}

void ConfirmGone::onStart(HandoverContext& ctx) {
  ctrl().relaxHandClearance(true);  // the hand and the gripper share the object now
  since_ = -1.0;
  ctrl().enableTracking(false);
  hold_ = ctx.in.tcp_pose;
  ride_.start(ctx);
  ctrl().setPoseTarget(hold_);
}

bool ConfirmGone::onRun(HandoverContext& ctx) {
  ride_.hold(ctrl(), hold_, ctx.in);
  const double weight = ctx.object.mass * ctx.params->gravity;
  // the wrist lost gone_fraction of the weight since the hold was recorded,
  // or the robot carries at most the rest of it (load share): a receiver who
  // took part of the weight before the hold was recorded leaves less to lose
  const double removed = -ctx.addedWeight(ctx.force_holding);
  const bool left = removed >= fraction_ * weight || ctx.in.load_share <= 1.0 - fraction_;
  if (ctx.in.finger_width < min_width_ || !left) {
    since_ = -1.0;
    return false;
  }
  if (since_ < 0.0) since_ = ctx.time;
  if (ctx.time - since_ < hold_time_) return false;
  ctrl().clearPayload();
  ctx.exchanged = true;
  setOutput(gone_);
  return true;
}

}  // namespace handover::fsm
