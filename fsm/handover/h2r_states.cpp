#include "fsm/handover/h2r_states.hpp"

#include <algorithm>
#include <cmath>

#include "fsm/handover/grasp_funnel.hpp"
#include "fsm/handover/perception_checks.hpp"
#include "fsm/handover/presentation_descent.hpp"
#include "fsm/handover/tracking_setup.hpp"

namespace handover::fsm {

namespace {
/// The funnel's keys next to a standoff (m) already read.
void readFunnel(const YamlReader& def, double standoff, GraspFunnel& funnel) {
  funnel.max_standoff = standoff;
  funnel.speed = HandoverState::readPositive(def, "standoff_speed", 1.0);
  if (def.has("standoff_acceleration")) funnel.acceleration = HandoverState::readPositive(def, "standoff_acceleration", 20.0);
  if (auto f = def.optionalChild("standoff_feed_forward")) funnel.feed_forward = f->asBool();
  if (funnel.acceleration > 0.0 && !funnel.feed_forward)
    def.child("standoff_acceleration").fail("a smooth slide is fed forward: needs standoff_feed_forward: true");
  funnel.margin = HandoverState::readRange(def, "funnel_margin", 0.0, 1.0);
  if (def.has("mouth_clearance")) funnel.mouth_clearance = HandoverState::readRange(def, "mouth_clearance", 0.0, standoff);
  if (def.has("motion_horizon")) {
    funnel.motion_horizon = HandoverState::readRange(def, "motion_horizon", 0.0, 1.0);
    funnel.motion_significance = HandoverState::readRange(def, "motion_significance", 0.0, 10.0);
  }
}

/// One step of `funnel`'s slide toward `goal` (m) from the standoff tracked now, sent to the
/// tracking (with `shift`) when it moves or its rate changes; backing out up to `extra_speed`
/// (m/s) faster than its own. Returns the standoff (m).
double slideToward(HandoverContext& ctx, ControllerHandle& ctrl, GraspFunnel& funnel, double goal,
                   const Vector3& shift, double extra_speed = 0.0) {
  const GraspFunnel::Slide slide =
      funnel.step(ctx.tracking_standoff, ctx.tracking_standoff_rate, goal, ctx.time, extra_speed);
  if (slide.standoff != ctx.tracking_standoff || slide.rate != ctx.tracking_standoff_rate)
    setStandoff(ctx, ctrl, false, slide.standoff, shift, slide.rate, slide.acceleration);
  return slide.standoff;
}

/// N: what pushes the gripper back against its approach axis (the TCP's z).
double pushBack(const HandoverInput& in) { return -in.tool_contact.head<3>().dot(in.tcp_pose.linear().col(2)); }

/// How the object sits between the open fingers for `grasp` (world), and where its motion takes
/// it within `funnel`'s motion horizon (budgetMotion; an object not seen now: as last seen).
FingerFit fitFor(const HandoverContext& ctx, const Isometry& object, const Isometry& grasp, const GraspFunnel& funnel) {
  FingerFit f = fingerFit(ctx.in.tcp_pose, object, grasp, ctx.object.shape, ctx.params->gripper_open_width,
                          ctx.params->finger_half_span);
  if (fresh(ctx.in.object, ctx.params->max_data_age))
    budgetMotion(f, grasp, ctx.in.object.velocity.head<3>(), ctx.in.tcp_velocity.head<3>(), ctx.in.object.speed_std,
                 funnel.motion_horizon, funnel.motion_significance);
  return f;
}
}  // namespace

WaitForPerson::WaitForPerson(bool hand)
    : hand_(hand), out_(declareOutput(hand ? "ReceiverComing" : "Offered")) {}

void WaitForPerson::configure(const YamlReader& def) {
  approach_speed_ = readPositive(def, "approach_speed", 5.0);
  settle_speed_ = readPositive(def, "settle_speed", 5.0);
  settle_time_ = readRange(def, "settle_time", 0.0, 10.0);
  if (def.has("home_radius")) home_radius_ = readRange(def, "home_radius", 0.0, 1.0);
  if (def.has("home_rest_time")) {
    if (!def.has("home_radius")) def.child("home_rest_time").fail("a rest at home needs home_radius");
    home_rest_time_ = readRange(def, "home_rest_time", settle_time_, 60.0);
  }
  if (def.has("approach_significance")) significance_ = readRange(def, "approach_significance", 0.0, 10.0);
  if (def.has("carried_in_distance")) carried_in_ = readRange(def, "carried_in_distance", 0.0, 1.0);
  if (def.has("pull_hold_time") && !hand_) def.child("pull_hold_time").fail("only a give's wait (for the receiver) is taken from");
  if (take_.configure(def)) pulled_ = declareOutput("Pulled");
  if (auto w = def.optionalChild("withdrawn_at_home"); w && w->asBool()) {
    if (!def.has("home_radius")) w->fail("a person back home needs home_radius");
    withdrawn_ = declareOutput("Withdrawn");
  }
}

void WaitForPerson::onStart(HandoverContext& ctx) {
  rest_.reset();
  take_.restart();
  ctrl().enableTracking(false);
  ctrl().setObservationTarget(hand_ ? ObservationTarget::kHand : ObservationTarget::kObject);
  ctrl().setPoseTarget(ctx.in.tcp_pose);  // at rest while waiting
}

bool WaitForPerson::onRun(HandoverContext& ctx) {
  const HandoverParams& p = *ctx.params;
  const SensedBody& body = hand_ ? ctx.in.hand : ctx.in.object;
  if (take_.taken(ctx)) {
    cameBack(ctx);
    setOutput(pulled_);
    return true;
  }
  // where the reach will end: a person bringing the object in is seen as coming once the
  // reach's end is known, before the object arrives. (Any motion toward the robot from anywhere
  // was tried: the noisy velocity of a person standing still started 33 of 300 approaches
  // that ended withdrawn at once, a retry lost each.)
  const Vector3 pos = (p.anticipate_reach ? restPose(body) : body.pose).translation();
  const Vector3* home = homeOf(ctx, hand_);
  const bool at_home = home_radius_ > 0.0 && home != nullptr && (pos - *home).norm() < home_radius_;
  // back where it was first seen after it had been out of that circle: the person withdrew before
  // the arm came (a receiver who reached while it went to its ready pose), in or out of the workspace.
  // How far it went is low-passed (a transient is no excursion), so out is out: a receiver who went
  // 9.7 cm out and back (under twice home_radius, the rule before) was served at their hip (g1051_00727)
  const bool back_home = at_home && farthestFromHome(ctx, hand_) > home_radius_;
  if (withdrawn_ >= 0 && back_home && fresh(body, p.max_data_age)) {
    ++ctx.stats.aborts;  // as a Retreat counts it: coming back is a retry
    ctx.retry_pending = ctx.stats.retries < p.max_retries;
    setOutput(withdrawn_);
    return true;
  }
  // the workspace, or its edge where the arm's own kinematics reach the body (the planner's IK):
  // inside the band a person must leave to count as withdrawn (withdraw.workspace_margin), so an
  // approach it starts is not ended at once. A receiver's hand 5 mm past the box's side was never
  // taken for one that came, and the give ended aborted (g421_00123)
  constexpr double kRestPlace = 0.05;  // m, as WaitAgain's home_radius: still where it was first seen
  // (how far it went, low-passed: a young track's prediction from a few noisy samples put the object
  // 5 cm off for 15 ms, and the arm set off toward a person who had not moved, h2r_noise_1cm)
  const bool left_home = home != nullptr && fromHome(ctx, hand_) > std::max(kRestPlace, home_radius_);
  const bool in_workspace = inWorkspace(ctx, hand_) || (left_home && latestPlan(ctx, hand_).valid &&
                                                        inWorkspace(ctx, hand_, p.withdraw_workspace_margin));
  const bool usable = fresh(body, p.max_data_age) && in_workspace && (!hand_ || ctx.in.hand_open);
  if (!usable) {
    rest_.reset();
    return false;
  }
  // coming: toward the robot faster than approach_speed by more than `significance_` standard
  // deviations of the velocity estimate (a track two samples old of a hand at rest reads the
  // sensor's noise as 0.1-0.25 m/s: approaches began 0.04 s into the run, the arm on its way to
  // a person who had not moved yet and then brought the object in across its path)
  bool ready = speedToward(p.workspace.center, body) - significance_ * body.speed_std > approach_speed_;
  // resting, on its displacement (rest_window.hpp): a person holding the object still after a
  // dropout was never seen to rest by the noisy speed, and the robot gave up on them
  // within reach: near the shoulder, or where the arm's own kinematics reach it (the planner's IK),
  // not at the place the person held it before they offered it (a rest there is no offer)
  const bool within_reach =
      (pos - p.workspace.center).norm() <= p.reach_radius || (left_home && latestPlan(ctx, hand_).valid);
  // or carried in: moved on, within reach, carried_in_distance from where it was first seen and not
  // away from the robot. Brought in from beside the table, an object crosses the robot's front more
  // than it comes nearer (9 cm nearer the shoulder in a 1.7 s reach): it was taken for an offer only
  // once it rested, the arm 0.5 m away (hand still to grasp 2.5-4.5 s, seed 631)
  if (carried_in_ > 0.0 && home != nullptr && within_reach && (pos - *home).norm() > carried_in_ &&
      body.velocity.head<3>().norm() - significance_ * body.speed_std > approach_speed_ &&
      speedToward(p.workspace.center, body) >= 0.0)
    ready = true;
  // at home a rest is an offer only once it lasted home_rest_time (a person holding the object
  // out where they stand and waiting), with the same tolerance on its displacement (back home
  // after going out, withdrawn_at_home has ended the wait above)
  const double window = at_home ? home_rest_time_ : settle_time_;
  if (!within_reach || (at_home && home_rest_time_ <= 0.0)) {
    rest_.reset();
  } else {
    ready = rest_.rests(pos, ctx.time, window > 0.0 ? settle_speed_ * settle_time_ / window : settle_speed_, window) ||
            ready;
  }
  if (ready) {
    cameBack(ctx);
    setOutput(out_);
  }
  return ready;
}

void WaitForPerson::cameBack(HandoverContext& ctx) {
  if (!ctx.retry_pending) return;
  ++ctx.stats.retries;
  ctx.retry_pending = false;
}

Approach::Approach(bool hand)
    : hand_(hand), near_(declareOutput("Near")), withdrawn_(declareOutput("Withdrawn")) {}

void Approach::configure(const YamlReader& def) {
  near_distance_ = readPositive(def, "near_distance", 1.0);
  if (def.has("near_orientation_deg")) near_orientation_ = readPositive(def, "near_orientation_deg", 180.0) * M_PI / 180.0;
  if (def.has("standoff")) standoff_ = readRange(def, "standoff", 0.0, 0.3);
  if (def.has("funnel_margin")) {
    if (hand_) def.child("funnel_margin").fail("only an approach to the object (a take) slides in through the funnel");
    if (standoff_ <= 0.0) def.fail("a funnel (funnel_margin) needs a standoff > 0, its mouth");
    readFunnel(def, standoff_, funnel_);
  }
  if (def.has("lift")) {
    if (!hand_) def.child("lift").fail("only an approach to the hand (a give) has a lift");
    lift_ = readRange(def, "lift", 0.0, 0.3);
    lift_speed_ = readPositive(def, "lift_speed", 2.0);
  }
  if (def.has("pull_hold_time") && !hand_) def.child("pull_hold_time").fail("only an approach to the hand (a give) is taken from");
  if (def.has("yield_force")) {
    if (hand_) def.child("yield_force").fail("only an approach to the object (a take) has an empty gripper to feel a strike");
    yield_force_ = readRange(def, "yield_force", 1.0, 500.0);
  }
  if (take_.configure(def)) pulled_ = declareOutput("Pulled");
  stall_.configure(def);
}

void Approach::onStart(HandoverContext& ctx) {
  blind_ = false;
  struck_ = false;
  withdrawal_.restart();
  take_.restart();
  stall_.restart(ctx.time);
  last_time_ = ctx.time;
  // take: meet the object where the person's reach will end. Not in a give: the receiver
  // reaches for the object, so going where their hand will stop met it halfway (seed 1: 10 gives
  // lost, 3 gained; strikes, timeouts)
  if (!hand_ && ctx.params->anticipate_reach) ctrl().anticipateRest(true);
  trackedChoice(ctx, hand_).adopt(latestPlan(ctx, hand_));
  trackTarget(ctx, ctrl(), hand_, standoff_, TrackingGains::kFollow,
              hand_ && lift_ > 0.0 ? descentShift(ctx, lift_) : Vector3::Zero().eval());
  if (!hand_) ctrl().setGripper(ctx.params->gripper_open_width, ctx.params->gripper_force);
  funnel_.restart(ctx.time);
}

bool Approach::slideIn(HandoverContext& ctx, bool arrived) {
  // still brought in: lined up at the full standoff (a stiff slide onto an object that still
  // moves would strike it; at the mouth, a lying tube brought in at 1.3 m/s struck the gripper:
  // g533_00010); arrived: from the mouth (the fingertips just in front of it) in as it fits
  const Isometry grasp = trackedGraspFrame(ctx);
  FingerFit f = fitFor(ctx, ctx.in.observed_pose, grasp, funnel_);
  const double mouth = funnel_.mouth(f, ctx.params->finger_pad_reach);
  double goal = funnel_.lineUp(f, ctx.params->finger_pad_reach);
  if (arrived) {
    // Grasp's fit, and on the approach line across the closing axis too: the slide goes
    // along the line, not diagonally past the hand that holds the object
    f.fit -= std::abs((grasp.translation() - ctx.in.tcp_pose.translation()).dot(grasp.linear().col(0)));
    goal = funnelStandoff(f, mouth, funnel_.margin);
  }
  // the TCP in the grasp frame: past the mouth along the approach axis and off the approach line
  // by more than it must be near it to arrive (near_distance), the gripper stands beside the
  // object or on its edge, not in front of it
  const Vector3 tcp = grasp.inverse() * ctx.in.tcp_pose.translation();
  const double off_line = tcp.head<2>().norm();
  const bool beside = tcp.z() > -mouth && off_line > near_distance_;
  if (stall_.detouring()) {
    // stalled there (the palm against a tube's side, g881_00174: 12 cm short for 10 s; the finger
    // capsule on a box's edge, g907_00138: 4 cm):
    // line up in front of it again, as far back along the axis as the TCP is off the line, so
    // the way to the line-up point leads away from the object; back on the line, the funnel goes on
    if (off_line <= near_distance_)
      stall_.restart(ctx.time);  // progress is owed again from here
    else
      goal = std::max(goal, mouth + off_line);
  }
  const double standoff = slideToward(ctx, ctrl(), funnel_, goal, ctx.tracking_shift, f.closing_speed);
  // in the funnel the gripper and the hand share the object, as in Grasp: the rules that keep
  // the fingers off the object and apart from the hand would stop the slide short of it
  ctrl().relaxHandClearance(standoff < mouth - 1e-6);
  return beside;
}

bool Approach::onRun(HandoverContext& ctx) {
  const SensedBody& body = hand_ ? ctx.in.hand : ctx.in.object;
  const bool blind = !fresh(body, ctx.params->max_data_age);
  if (blind && !blind_) {
    stall_.restart(ctx.time);  // unseen: no progress is owed, and tracking resumes with the next sample
    ctrl().enableTracking(false);
    ctrl().setPoseTarget(ctx.in.tcp_pose);  // hold: no motion toward a person it cannot see
  } else if (!blind && blind_) {
    trackedChoice(ctx, hand_).adopt(latestPlan(ctx, hand_));
    trackTarget(ctx, ctrl(), hand_, standoff_, TrackingGains::kFollow, ctx.tracking_shift);
  }
  blind_ = blind;
  // before the withdrawal: the hand that leaves with the object it pulled is the handover
  if (take_.taken(ctx)) {
    setOutput(pulled_);
    return true;
  }
  const double dt = ctx.time - last_time_;
  last_time_ = ctx.time;
  const bool arrived = ctx.params->arrive_speed <= 0.0 || body.velocity.head<3>().norm() <= ctx.params->arrive_speed;
  const TrackingPlan& plan = latestPlan(ctx, hand_);
  if (!blind && stall_.moving()) {
    // in joint space to where the planner's IK reaches the target; tracking again from there
    if (stall_.finished(ctx, arrived, plan.valid ? plan.index : -1))
      trackTarget(ctx, ctrl(), hand_, ctx.tracking_standoff, TrackingGains::kFollow, ctx.tracking_shift);
  } else if (!blind) {
    // the best reachable target as the person moves (a new grasp starts from the funnel's mouth)
    const bool switched = followPlan(ctx, ctrl(), hand_, standoff_);
    const bool beside = funnel_.enabled() && !switched && slideIn(ctx, arrived);
    if (hand_ && lift_ > 0.0) followDescent(ctx, ctrl(), lift_, lift_speed_, dt);
    // the gains follow the tracked target's speed: a take's target (where the reach ends) stands
    // still once it is known; a give's is the receiver's hand itself
    // struck: the empty gripper pushed harder than yield_force (the object or the hand is not where
    // the sensor says; a tracker 10 cm low): the rest of the approach at the soft follow gains. At
    // arrive gains of 150 (tried) the arm pressed on with 100 N and spun joint 6 past its limits
    if (yield_force_ > 0.0 && ctx.in.tool_contact.head<3>().norm() > yield_force_) struck_ = true;
    if (struck_)
      setTrackingGains(*ctx.params, ctrl(), TrackingGains::kFollow);
    else
      setPhaseGainsForSpeed(*ctx.params, ctrl(), TrackingGains::kFollow,
                            (hand_ ? body.velocity : ctx.in.target_velocity).head<3>().norm(), !hand_);
    stall_.watch(ctx, ctrl(), hand_, positionError(ctx.in.tcp_pose, ctx.in.target_pose), arrived, plan.valid,
                 beside);
  }
  if (withdrawal_.withdrawn(ctx, hand_)) {
    setOutput(withdrawn_);
    return true;
  }
  // near, and the body arrived: the next phase's stiff gains meet a body at rest, not one still brought in.
  // A take is near its pre-grasp (the standoff is the line-up, or the funnel's target as the fingers
  // slide in); a give is near the presentation itself, not the descent's raised target (which stands
  // above the TCP while it rises)
  const Isometry near_target = hand_ ? trackedGraspFrame(ctx) : ctx.in.target_pose;
  if (!blind && !stall_.moving() && arrived && positionError(ctx.in.tcp_pose, near_target) <= near_distance_ &&
      rotationError(ctx.in.tcp_pose, near_target) <= near_orientation_) {
    setOutput(near_);
    return true;
  }
  return false;
}

Grasp::Grasp()
    : grasped_(declareOutput("Grasped")), missed_(declareOutput("Missed")), withdrawn_(declareOutput("Withdrawn")) {}

void Grasp::configure(const YamlReader& def) {
  pos_tol_ = readPositive(def, "position_tolerance", 0.2);
  rot_tol_ = readPositive(def, "orientation_tolerance_deg", 180.0) * M_PI / 180.0;
  confirm_time_ = readRange(def, "confirm_time", 0.0, 5.0);
  stall_speed_ = readPositive(def, "stall_speed", 1.0);
  if (def.has("standoff")) readFunnel(def, readRange(def, "standoff", 0.0, 0.3), funnel_);
  if (def.has("touch_force")) {
    touch_force_ = readRange(def, "touch_force", 0.0, 100.0);
    touch_time_ = readRange(def, "touch_time", 0.0, 1.0);
    max_touches_ = static_cast<int>(readRange(def, "max_touches", 0.0, 10.0));
  }
  if (def.has("jam_force")) {
    jam_force_ = readRange(def, "jam_force", 1.0, 1000.0);
    jam_time_ = readRange(def, "jam_time", 0.0, 2.0);
  }
  if (def.has("regrips")) max_regrips_ = static_cast<int>(readRange(def, "regrips", 0.0, 5.0));
  if (def.has("release_distance")) release_distance_ = readRange(def, "release_distance", 0.0, 0.3);
  if (def.has("regrip_max_share")) regrip_max_share_ = readRange(def, "regrip_max_share", 0.0, 1.0);
}

void Grasp::onStart(HandoverContext& ctx) {
  ctrl().relaxHandClearance(true);  // the hand and the gripper share the object now
  closing_ = false;
  withdrawal_.restart();
  pull_.restart();
  carried_.restart();
  funnel_.restart(ctx.time);
  touches_ = 0;
  touch_since_ = -1.0;
  touch_felt_ = false;
  jam_since_ = -1.0;
  touch_shift_.setZero();
  regrips_ = 0;
  reopening_ = false;
  if (funnel_.acceleration > 0.0) {
    // the slide goes on from where the approach left it, at its rate (fed forward): a
    // jump of the target to the funnel's goal left the TCP to the PD's slow tail
    const double rate = ctx.tracking_standoff_rate;
    trackTarget(ctx, ctrl(), false, ctx.tracking_standoff, TrackingGains::kAlign);
    if (rate != 0.0) setStandoff(ctx, ctrl(), false, ctx.tracking_standoff, touch_shift_, rate);
  } else {
    const FingerFit f = fitNow(ctx);
    const double mouth = funnel_.mouth(f, ctx.params->finger_pad_reach);
    trackTarget(ctx, ctrl(), false, std::min(ctx.tracking_standoff, funnelStandoff(f, mouth, funnel_.margin)),
                TrackingGains::kAlign);
  }
}

Isometry Grasp::correctedGraspFrame(const HandoverContext& ctx) const {
  Isometry g = trackedGraspFrame(ctx);
  g.translation() += ctx.in.observed_pose.linear() * touch_shift_;
  return g;
}

Isometry Grasp::correctedObject(const HandoverContext& ctx) const {
  Isometry object = ctx.in.observed_pose;
  object.translation() += object.linear() * touch_shift_;
  return object;
}

FingerFit Grasp::fitNow(const HandoverContext& ctx) const {
  const Isometry object = correctedObject(ctx);
  const Isometry grasp = correctedGraspFrame(ctx);
  FingerFit f = fitFor(ctx, object, grasp, funnel_);
  f.hold_depth = hold_depth_.get(ctx.object.shape, object.inverse() * grasp, ctx.params->grip_friction);
  return f;
}

double Grasp::closingTime(const HandoverContext& ctx, const FingerFit& f) const {
  const HandoverParams& p = *ctx.params;
  if (p.gripper_closing_speed <= 0.0) return 0.0;
  // the gap the fingers close before they meet the object: twice the clearance per side
  // (the whole opening for an object of unknown shape)
  const double gap = f.clearance < 0.5 * p.gripper_open_width ? 2.0 * f.clearance : ctx.in.finger_width;
  return std::max(0.0, gap) / p.gripper_closing_speed;
}

bool Grasp::feelTouch(HandoverContext& ctx, const FingerFit& f) {
  const Eigen::Matrix3d& tcp = ctx.in.tcp_pose.linear();
  // the contact pushes the gripper back against its approach axis (z); a force p at
  // a along the closing axis (y) turns it about x by -a p
  const double push = pushBack(ctx.in);
  if (push < touch_force_) {
    touch_since_ = -1.0;
    if (push < 0.5 * touch_force_) touch_felt_ = false;  // the push ended: a new one is a new touch
    return false;
  }
  if (touch_since_ < 0.0) touch_since_ = ctx.time;
  if (touch_felt_ || touches_ >= max_touches_ || ctx.time - touch_since_ < touch_time_) return false;
  touch_felt_ = true;
  const double lever = -ctx.in.tool_contact.tail<3>().dot(tcp.col(0)) / push;
  // on the palm between the fingers (|lever| small) the object is in: no side to correct
  if (std::abs(lever) < 0.25 * ctx.params->gripper_open_width || f.clearance > 1e6) return false;
  ++touches_;
  const Vector3 toward = (lever > 0.0 ? 1.0 : -1.0) * f.clearance * tcp.col(1);
  touch_shift_ += ctx.in.observed_pose.linear().transpose() * toward;
  setStandoff(ctx, ctrl(), false, ctx.tracking_standoff, touch_shift_);
  return true;
}

bool Grasp::jammed(const HandoverContext& ctx) {
  if (jam_force_ <= 0.0) return false;
  if (pushBack(ctx.in) < jam_force_) {
    jam_since_ = -1.0;
    return false;
  }
  if (jam_since_ < 0.0) jam_since_ = ctx.time;
  return ctx.time - jam_since_ >= jam_time_;
}

bool Grasp::regrip(HandoverContext& ctx) {
  if (regrips_ >= max_regrips_ || !hand_at_close_known_ || !fresh(ctx.in.hand, ctx.params->max_data_age) ||
      (ctx.in.hand.pose.translation() - hand_at_close_).norm() > release_distance_ ||
      ctx.in.load_share >= regrip_max_share_)
    return false;  // the person may have let go (moved off, or the weight coming over): opening now would drop it
  const FingerFit f = fitNow(ctx);
  if (f.near_face > 1e6 || !(f.hold_depth > 0.0)) return false;
  const Isometry object = correctedObject(ctx);
  const Isometry grasp = correctedGraspFrame(ctx);
  // where the object is as wide as the fingers closed: there the pads' tips are
  const double tips = depthOfWidth(ctx.object.shape, object.inverse() * grasp, ctx.in.finger_width);
  if (tips < 0.0 || tips >= f.hold_depth) return false;
  ++regrips_;
  // in by the shortfall: the tips to where the grasp puts them (the near face, then pad_reach on)
  const double shortfall = f.near_face + ctx.params->finger_pad_reach - tips;
  regrip_shift_ = object.linear().transpose() * (shortfall * grasp.linear().col(2));
  reopening_ = true;
  closing_ = false;
  ctrl().setGripper(ctx.params->gripper_open_width, ctx.params->gripper_force);
  return true;
}

bool Grasp::onRun(HandoverContext& ctx) {
  if (reopening_) {
    // the fingers off the object before the grasp moves in (closed, they would drag it along)
    constexpr double kOpenTolerance = 0.005;  // m: the width reading settles this near the opening
    if (ctx.in.finger_width < ctx.params->gripper_open_width - kOpenTolerance) return false;
    reopening_ = false;
    touch_shift_ += regrip_shift_;
    setStandoff(ctx, ctrl(), false, ctx.tracking_standoff, touch_shift_);
  }
  if (!closing_) {
    // withdrawn, or taking it away through the open fingers: the object they carry off
    // pushes a finger toward where they came from, and the way their hand goes, long before
    // the motion tells a withdrawal (a tube pulled across the fingers struck one at 60-330 N,
    // g1019_00215)
    const bool carried = carried_.carried(ctx, touch_time_, funnel_.motion_significance);  // every cycle: its hold
    if (withdrawal_.withdrawn(ctx, false) || pull_.pulled(ctx, touch_time_) || carried) {
      setOutput(withdrawn_);
      return true;
    }
    if (jammed(ctx)) {
      setOutput(missed_);
      return true;
    }
    setPhaseGainsForSpeed(*ctx.params, ctrl(), TrackingGains::kAlign, ctx.in.object.velocity.head<3>().norm());
    FingerFit f = fitNow(ctx);
    if (touch_force_ > 0.0 && feelTouch(ctx, f)) f = fitNow(ctx);  // the corrected grasp's fit
    // the funnel's standoff, reached at standoff_speed (the fit is as noisy as the object's pose)
    slideToward(ctx, ctrl(), funnel_, funnelStandoff(f, funnel_.mouth(f, ctx.params->finger_pad_reach), funnel_.margin),
                touch_shift_, f.closing_speed);
    // closes only on an object between the fingers (the funnel's last part), and between
    // the pads along the approach axis when they meet it (a thin object fits across long before)
    const Isometry grasp = correctedGraspFrame(ctx);
    const double lead = closingTime(ctx, f);
    const Vector3 approach = grasp.linear().col(2);
    const double along = (ctx.in.tcp_pose.translation() - grasp.translation()).dot(approach) +
                         lead * (ctx.in.tcp_velocity - ctx.in.target_velocity).head<3>().dot(approach);
    // and with the pads already where the object's side holds them (a round one): judged on the
    // object's estimate, not the observed object, which lags one that still moves (1 cm at 0.2 m/s)
    const bool seen = fresh(ctx.in.object, ctx.params->max_data_age);
    const Vector3 grasp_now =
        seen ? Vector3(ctx.in.object.pose * (ctx.in.observed_pose.inverse() * grasp.translation())) : grasp.translation();
    const double along_now = (ctx.in.tcp_pose.translation() - grasp_now).dot(approach);
    if (f.fit <= 0.0 || positionError(ctx.in.tcp_pose, grasp) > pos_tol_ ||
        !alignedWhenClosed(ctx.in, pos_tol_, rot_tol_, lead) ||
        !deepEnough(f, along, ctx.params->finger_pad_reach, ctx.params->grip_depth) ||
        !holdsWhenClosed(f, along_now, ctx.params->finger_pad_reach))
      return false;
    ctx.force_before_grasp = ctx.force;  // reference for the release test
    ctrl().setGripper(ctx.params->gripper_close_width, ctx.params->gripForce(ctx.object.mass, ctx.comInTcp()));
    // the fingers centre the gripper on the object now: an arm that gives way to them
    const HandoverParams& p = *ctx.params;
    if (p.closing_tracking_translation_stiffness > 0.0 && p.closing_tracking_orientation_stiffness > 0.0)
      ctrl().setTrackingStiffness(p.closing_tracking_translation_stiffness, p.closing_tracking_orientation_stiffness);
    closing_ = true;
    pull_.restart();
    closed_at_ = last_time_ = ctx.time;
    last_width_ = ctx.in.finger_width;
    finger_speed_ = 1e9;
    hand_at_close_known_ = fresh(ctx.in.hand, ctx.params->max_data_age);
    if (hand_at_close_known_) hand_at_close_ = ctx.in.hand.pose.translation();
    return false;
  }
  // the person takes it back as the fingers close (WaitForRelease's rule): let them. And
  // one who withdraws while the fingers still close freely, before they hold anything,
  // withdraws as before the close: closed on an object pulled away at 0.8 m/s, the fingers
  // caught it and the pull spun the wrist past its velocity limit before it slipped out
  if (pull_.pulled(ctx, touch_time_) || (finger_speed_ > stall_speed_ && withdrawn(ctx, false))) {
    setOutput(withdrawn_);
    return true;
  }
  // closing while the slide still runs (the TCP within the tolerance of the grasp): it
  // ends at the grasp, not frozen mid-way with its rate still fed forward
  if (funnel_.feed_forward) slideToward(ctx, ctrl(), funnel_, 0.0, touch_shift_);
  // finger speed over >= 10 ms windows: robust to quantised width readings
  if (ctx.time - last_time_ >= 0.01) {
    finger_speed_ = std::abs(ctx.in.finger_width - last_width_) / (ctx.time - last_time_);
    last_width_ = ctx.in.finger_width;
    last_time_ = ctx.time;
  }
  if (ctx.time - closed_at_ < confirm_time_ || finger_speed_ > stall_speed_) return false;
  const bool holds = ctx.in.finger_width > ctx.params->gripper_empty_width;
  if (holds && regrip(ctx)) return false;
  setOutput(holds ? grasped_ : missed_);
  return true;
}

WaitForRelease::WaitForRelease() : released_(declareOutput("Released")), withdrawn_(declareOutput("Withdrawn")) {}

void WaitForRelease::configure(const YamlReader& def) {
  if (def.has("release_share")) {
    share_ = readRange(def, "release_share", 0.05, 1.0);
    distance_ = readRange(def, "release_distance", 0.0, 0.3);
    wait_ = readRange(def, "release_wait", 0.0, 60.0);
    hold_share_ = def.has("hold_share") ? readRange(def, "hold_share", 0.05, share_) : share_;
    if (def.has("release_fraction")) def.child("release_fraction").fail("give release_share or release_fraction, not both");
  } else if (def.has("release_fraction")) {
    fraction_ = readPositive(def, "release_fraction", 2.0);
  } else {
    def.fail("needs release_share (the robot's load share, 0..1) or release_fraction (of m g)");
  }
  hold_time_ = readRange(def, "hold_time", 0.0, 5.0);
  if (def.has("motion_significance")) significance_ = readRange(def, "motion_significance", 0.0, 10.0);
}

void WaitForRelease::onStart(HandoverContext& ctx) {
  ctrl().relaxHandClearance(true);  // the hand and the gripper share the object now
  // and the fingers hold it: the clearance they kept from the hand while closing has
  // nothing left to do (they cannot leave it without the object); against a hand touching
  // them it turned the wrist at its speed limit instead (g1097_00374)
  ctrl().fingersAroundObject(true);
  since_ = -1.0;
  holding_ = false;
  hand_started_ = false;
  carry_since_ = -1.0;
  pull_.restart();
  carried_.restart();
  // follow the object while the person still holds it, where the fingers closed on it
  // (the grasp as Grasp corrected it by touch: ctx.tracking_shift)
  trackTarget(ctx, ctrl(), false, 0.0, TrackingGains::kFollow, ctx.tracking_shift);
}

void WaitForRelease::hold(HandoverContext& ctx) {
  ctrl().enableTracking(false);
  ctrl().setPoseTarget(ctx.in.tcp_pose);
  // as stiff as the closing fingers were held
  holdAtClosingGains(*ctx.params, ctrl());
  holding_ = true;
}

bool WaitForRelease::onRun(HandoverContext& ctx) {
  const bool hand_seen = fresh(ctx.in.hand, ctx.params->max_data_age);
  // the hand where it grips the object, as the gripper that holds the object sees it (the
  // TCP's frame), and beside the gripper along the world's axes: it has left its grip once it
  // moved away in both. In the TCP's frame alone, a wrist that turned 7 degrees under the load
  // while the person still held on moved the hand 1.5 cm (a 6 cm lever, s_08: the robot
  // retracted against their grip and lost the mug); along the world's axes alone, a hand
  // that turns with the wrist moves as much
  const Vector3 hand_rel = ctx.in.hand.pose.translation() - ctx.in.tcp_pose.translation();
  const Vector3 hand_at = ctx.in.tcp_pose.linear().transpose() * hand_rel;
  if (hand_seen && !hand_started_) {
    hand_start_ = hand_at;
    hand_start_world_ = hand_rel;
    hand_started_ = true;
  }
  const double hand_moved = std::min((hand_at - hand_start_).norm(), (hand_rel - hand_start_world_).norm());
  const double weight = ctx.object.mass * ctx.params->gravity;
  const bool carries = share_ >= 0.0 ? ctx.in.load_share >= share_
                                     : ctx.addedWeight(ctx.force_before_grasp) >= fraction_ * weight;
  // the person takes the object back: the fingers let them have it. Holding on, the arm
  // was dragged after a person who withdrew as the fingers closed (retries, aborts: joints
  // past their velocity limits). Felt and seen: a pull toward them, their hand going that
  // way (the object's estimate sits in that hand until the robot holds it, so the hand
  // alone cannot tell a person who let go and leaves). Not the load share: a pull down and
  // away reads as the object's weight. Nor only across the floor: a person withdrawing
  // down and back pulled 20 N along their hand's way, 10 N across the floor only once
  // their hand went 0.4 m/s, and the arm dragged after them spun joint 6 past its speed
  // limit (g1069_00050); the pull along the way the hand goes (carried) tells it 0.3 s sooner.
  // Going back toward where the hand was first seen: a person who moves the object on to
  // where they hand it over pulls it along their way too (outsider m_24, a relocation)
  const bool carried = carried_.carried(ctx, hold_time_, significance_, /*home_only=*/true);  // every cycle: its hold
  if (pull_.pulled(ctx, hold_time_) || carried || ctx.in.finger_width < ctx.params->gripper_empty_width) {
    setOutput(withdrawn_);
    return true;
  }
  // the robot bears most of the weight: hold still, not following the
  // object's estimate, which moves with the person's (leaving) hand and with
  // the object as it sinks. Held only once the whole load had come over, the
  // TCP followed the sinking object for the 0.1 s the share took to climb
  // from half to release_share (2 cm, g1_00538). The person takes most of it
  // back (the share falls below half of hold_share): follow again
  if (share_ >= 0.0) {
    if (!holding_ && ctx.in.load_share >= hold_share_) {
      hold(ctx);
    } else if (holding_ && ctx.in.load_share < 0.5 * hold_share_) {
      ctrl().clearPoseStiffness();
      trackTarget(ctx, ctrl(), false, 0.0, TrackingGains::kFollow, ctx.tracking_shift);
      holding_ = false;
    }
  }
  if (!carries) {
    since_ = carry_since_ = -1.0;
    return false;
  }
  if (since_ < 0.0) since_ = ctx.time;
  if (carry_since_ < 0.0) carry_since_ = ctx.time;
  // the person's hand is still on it; after release_wait with the whole load, let it be
  if (share_ >= 0.0 && hand_seen && hand_moved < distance_ && ctx.time - carry_since_ < wait_) {
    since_ = -1.0;
    return false;
  }
  if (ctx.time - since_ < hold_time_) return false;
  ctrl().setPayload(ctx.object.mass, ctx.comInTcp());
  ctx.exchanged = true;
  setOutput(released_);
  return true;
}

}  // namespace handover::fsm
