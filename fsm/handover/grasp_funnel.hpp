// The grasp funnel: how far back along its approach axis the gripper waits
// while the object does not yet fit between its open fingers.
//
// The fingers may only slide over the object once the object's slab across
// them lies inside the opening. A lateral error larger than the clearance
// (opening minus the object's width, per side: 6-9 mm for ordinary objects)
// lands a fingertip on the object: the gripper then pushes it instead of
// enclosing it, and the grasp never completes. So the standoff shrinks from
// its maximum (the fingertips in front of the object) to zero as the fit
// grows from nothing to half the clearance: the last slide keeps half the
// clearance as margin. A funnel along the approach axis, continuous in the
// alignment, instead of a stop-then-slide threshold.
//
// The fit: the clearance at perfect alignment (from the object's shape),
// less the lateral offset of the object's mid-plane from the fingers' and
// the widening a turned gripper causes, which is the turn (about the axes
// across the closing axis) times the finger's half span: a finger face
// meets the object over its own span, not the object's whole length.
//
// Frames: world poses; the TCP's and the grasp frame's y axis is the closing
// axis, z the approach axis (design notes). Units: m, rad. Real-time safe.
#pragma once

#include "fsm/handover/handover_io.hpp"

namespace handover::fsm {

/// How the object sits between the open fingers now.
struct FingerFit {
  /// m: room left between the object and the nearer finger (<= 0: a finger
  /// overlaps the object). Large when the shape is unknown.
  double fit = 1e9;
  /// m: the room per side at perfect alignment with the grasp frame
  /// (opening minus the object's width across the grasp's fingers, halved).
  double clearance = 1e9;
  /// m: the object's mid-plane from the fingers' along the closing axis (TCP
  /// y), signed; the fit loses its magnitude.
  double mid_plane = 0.0;
  /// m: the object behind the grasp point, back along the approach axis to
  /// its surface (the depth the pads can close on when the TCP is at the
  /// grasp; from the shape). Large when the shape is unknown.
  double near_face = 1e9;
  /// m: how deep along the approach axis, from the near face, the pads must
  /// meet the object for their squeeze to hold it (holdDepth, which fingerFit
  /// leaves to its caller: the scan is for once per grasp); 0: not asked.
  double hold_depth = 0.0;
  /// m: how far the gap to an object that comes toward the palm closes within
  /// the motion horizon (budgetMotion; 0 for one at rest or leaving): the
  /// standoff keeps it, on top of the funnel's (funnelStandoff) and in front
  /// of the near face while the object is still brought in (GraspFunnel::lineUp).
  double lead = 0.0;
  /// m/s: how fast the gap to an object that comes toward the palm closes
  /// (0: at rest or leaving): the funnel backs out at least this much faster.
  double closing_speed = 0.0;
};

/// m: the depth from the object's near face, along the grasp's approach axis
/// on the grasp line, from which the object's width across the closing axis
/// grows no faster than `friction` (mu) per unit depth. Pads that meet it
/// shallower press on a side that slopes away from them (a ball, a tube lying
/// across the fingers): the squeeze pushes the object out along the approach
/// axis harder than friction holds it (a tube of radius 23 mm closed on 12 mm
/// short of its axis stayed between the fingers until the retract, then
/// squeezed out). A flat face: about 0; a round section of radius r:
/// r (1 - mu / sqrt(1 + mu^2)). The near face itself when no depth is steep
/// enough. Frames: the object's; units m. RT safe (a scan of at most 400 steps).
double holdDepth(const io::ObjectShape& shape, const Isometry& grasp_in_object, double friction);

/// m: the shallowest depth from the object's near face, along the grasp's
/// approach axis on the grasp line, at which the object is `width` (m) wide
/// across the closing axis: where fingers that closed to `width` hold it,
/// if they hold it on the near side. -1 when the object is nowhere that wide
/// up to the grasp point (or its shape is unknown). Frames: the object's;
/// units m. RT safe (a scan of at most 400 steps).
double depthOfWidth(const io::ObjectShape& shape, const Isometry& grasp_in_object, double width);

/// holdDepth for a grasp that changes rarely (a new choice, a touch's
/// correction), as the 1 ms step needs it: the scan is redone only when the
/// grasp moved in the object frame by more than 1 mm or 0.02 rad, or the
/// shape or friction changed. RT safe.
class HoldDepthCache {
 public:
  double get(const io::ObjectShape& shape, const Isometry& grasp_in_object, double friction);

 private:
  bool valid_ = false;
  io::ObjectShape shape_;
  Isometry key_ = Isometry::Identity();
  double friction_ = 0.0, depth_ = 0.0;
};

/// m: how deep the finger pads reach into the object along the approach
/// axis with the TCP `along` (m) past the grasp point on that axis (negative:
/// short of it); the pads end `pad_reach` (m) past the TCP.
double padDepth(const FingerFit& f, double along, double pad_reach);

/// The pads reach deep enough into the object to close on it: `grip_depth`
/// (m), or half the depth the grasp itself gives where that is less (a grasp
/// declared near the surface). A thin object across the fingers (a phone
/// lying flat) fits laterally long before it lies between the pads: closed
/// 1.4 cm short, the fingertips met above it and landed on its top.
bool deepEnough(const FingerFit& f, double along, double pad_reach, double grip_depth);

/// The pads, with the TCP `along` (m) past the grasp point now, already reach
/// the object's hold depth (FingerFit::hold_depth), or half the depth the
/// grasp itself gives where that is less. Judged now, not at the predicted
/// contact: the slide slows as the fingers close, and a contact shallower
/// than planned is a round object squeezed out.
bool holdsWhenClosed(const FingerFit& f, double along, double pad_reach);

/// tcp, object, grasp: world poses (grasp = the frame the TCP should reach on
/// the object); opening: the open fingers' total gap, m; finger_half_span:
/// m, half a finger's contact face.
FingerFit fingerFit(const Isometry& tcp, const Isometry& object, const Isometry& grasp, const io::ObjectShape& shape,
                    double opening, double finger_half_span);

/// The fit `f` (for `grasp`, world) of an object that moves at `velocity`
/// (m/s, world: its estimate), each component known to `speed_std` (m/s),
/// the TCP moving at `tcp_velocity` (m/s, world). The arm meets the object's
/// motion only `horizon` (s) after it began: the observed object lags the
/// estimate by the observation's D / K, the estimate lags a sample, the
/// tracking lags its target. So:
/// - across the fingers the fit is taken where the object's mid-plane is by
///   then, moved on by its own way within the horizon, the TCP where it is.
///   Not the way relative to the TCP: an arm that follows the late estimate
///   is where the object was (tried on a cylinder withdrawn sideways from
///   under fingers around its top: 22 velocity-limit steps instead of 6);
/// - an object that comes toward the palm closes the gap at the speed
///   between it and the TCP along the approach axis (an arm on its way in
///   takes as long to turn back; one that already backs away with it takes
///   that off): that speed times horizon is the lead the standoff keeps (a
///   ball brought on at 0.6 m/s into a gripper on its way to it struck the
///   palm at 1.4 kN: the mouth's 2 cm were gone in 20 ms). The TCP's own way
///   in counts only then: onto an object at rest it slides at its set speed.
/// A component of the object's velocity within `significance` standard
/// deviations of 0 counts as 0 (a hand at rest reads its noise as speed).
/// RT safe.
void budgetMotion(FingerFit& f, const Isometry& grasp, const Vector3& velocity, const Vector3& tcp_velocity,
                  double speed_std, double horizon, double significance);

/// Standoff (m) along the approach axis for this fit: max_standoff while the
/// object does not fit, 0 once the fit keeps `margin` (a fraction of the
/// clearance) to spare, linear between; plus the fit's lead (an object
/// coming toward the palm).
double funnelStandoff(const FingerFit& f, double max_standoff, double margin);

/// The funnel over time: the standoff moves toward funnelStandoff at no more
/// than `speed` (the fit is as noisy as the object's pose) and, with an
/// `acceleration` limit, as a smooth slide: its rate changes by at most
/// `acceleration` and brakes in time to stop at the goal (the time-optimal
/// profile under both limits). The slide's rate and acceleration are what
/// the tracking feeds forward (TrackingOffset::approach_speed), so the TCP
/// slides with the target instead of lagging it. Configured by the states
/// that slide the fingers in (Approach, Grasp). RT safe.
struct GraspFunnel {
  double max_standoff = 0.0;  ///< m, the funnel's mouth (0: no funnel)
  double speed = 0.1;         ///< m/s, fastest change of the standoff
  double acceleration = 0.0;  ///< m/s^2, fastest change of its rate (0: none, the rate jumps)
  /// Report the slide's rate and acceleration (for the tracking's feed-forward);
  /// false: 0, the standoff a set-point the PD closes on (as shipped, docs/results.md)
  bool feed_forward = false;
  double margin = 0.5;        ///< share of the clearance the last slide keeps to spare
  /// m the fingertips wait in front of the object's near face at the funnel's
  /// mouth (< 0: the mouth is max_standoff whatever the object)
  double mouth_clearance = -1.0;
  /// s the arm meets the object's motion late by (budgetMotion; 0: the fit
  /// of an object at rest whatever it does)
  double motion_horizon = 0.0;
  double motion_significance = 2.0;  ///< standard deviations of a speed that are still noise
  double last_time = 0.0;     ///< s, the last step

  /// One step of the slide.
  struct Slide {
    double standoff = 0.0;      ///< m
    double rate = 0.0;          ///< m/s, d standoff / dt (negative: sliding in)
    double acceleration = 0.0;  ///< m/s^2, d rate / dt
  };

  bool enabled() const { return max_standoff > 0.0; }
  /// m: the funnel's mouth for the fit `f`: the standoff at which the
  /// fingertips (`pad_reach`, m, past the TCP) wait mouth_clearance in front
  /// of the object's near face, no farther back than max_standoff. Farther
  /// back is only a longer slide: the fingers cannot sweep over an object
  /// they are in front of. max_standoff for an unknown shape or a grasp
  /// outside the object.
  double mouth(const FingerFit& f, double pad_reach) const;
  /// m: the standoff while the object is still brought in (not yet at rest):
  /// max_standoff, or farther where an object coming at the palm needs it:
  /// the fingertips mouth_clearance plus the fit's lead in front of its near
  /// face (max_standoff plus the lead for an unknown shape). The line-up's
  /// own room in front of the object takes up the lead first: added on top
  /// of it, the lead of every object still brought in held the fingers back
  /// farther than its way needs (hand still to grasp +0.2 s on some takes).
  double lineUp(const FingerFit& f, double pad_reach) const;
  /// Restarts the rate limit at `time` (s).
  void restart(double time) { last_time = time; }
  /// The slide for this cycle from the standoff tracked now (`standoff`, m)
  /// moving at `rate` (m/s), toward `goal` (m; funnelStandoff of the fit, or
  /// max_standoff where the caller keeps the funnel closed). Backing out, up
  /// to `extra_speed` (m/s) faster than `speed`: an object coming at the
  /// palm is outrun (FingerFit::closing_speed).
  Slide step(double standoff, double rate, double goal, double time, double extra_speed = 0.0);

 private:
  Slide profile(double standoff, double rate, double goal, double time, double extra_speed);
  /// m: the standoff at which the fingertips wait mouth_clearance in front of
  /// the object's near face; -1 for an unknown shape, a grasp outside the
  /// object or no mouth_clearance (mouth and lineUp fall back on max_standoff).
  double clearOfFace(const FingerFit& f, double pad_reach) const;
};

}  // namespace handover::fsm
