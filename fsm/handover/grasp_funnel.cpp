#include "fsm/handover/grasp_funnel.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace handover::fsm {

namespace {
// a clearance below this counts as this (an object as wide as the opening
// would otherwise never be allowed in, and the scenario check admits it)
constexpr double kMinClearance = 0.001;
}  // namespace

namespace {
// The object's section along the grasp line: the near face's depth behind the grasp point and
// half the chord across the closing axis at depth s from it (s >= 0 into the object).
struct GraspLine {
  const io::ObjectShape& shape;
  Vector3 p, a, c;
  double near_face;
  GraspLine(const io::ObjectShape& sh, const Isometry& grasp_in_object)
      : shape(sh),
        p(grasp_in_object.translation()),
        a(grasp_in_object.linear().col(2)),
        c(grasp_in_object.linear().col(1)),
        near_face(io::exitDistance(sh, p, -a)) {}
  double halfWidth(double s) const {
    const Vector3 q = p - a * (near_face - s);
    return 0.5 * (io::exitDistance(shape, q, c) + io::exitDistance(shape, q, -c));
  }
  double step() const { return std::max(5e-4, near_face / 400.0); }  // at most 400 steps to the grasp point
};
}  // namespace

double holdDepth(const io::ObjectShape& shape, const Isometry& grasp_in_object, double friction) {
  if (!shape.known() || !(friction > 0.0)) return 0.0;
  const GraspLine line(shape, grasp_in_object);
  if (!(line.near_face > 0.0)) return 0.0;
  const double step = line.step();
  double w = line.halfWidth(step);
  for (double s = step; s + step <= line.near_face + 1e-12; s += step) {
    const double next = line.halfWidth(s + step);
    if (next - w <= friction * step) return s;
    w = next;
  }
  return line.near_face;
}

double depthOfWidth(const io::ObjectShape& shape, const Isometry& grasp_in_object, double width) {
  if (!shape.known()) return -1.0;
  const GraspLine line(shape, grasp_in_object);
  if (!(line.near_face > 0.0)) return -1.0;
  const double step = line.step();
  for (double s = step; s <= line.near_face + 1e-12; s += step)
    if (2.0 * line.halfWidth(s) >= width) return s;
  return -1.0;
}

double HoldDepthCache::get(const io::ObjectShape& shape, const Isometry& grasp_in_object, double friction) {
  const bool same = valid_ && shape.kind == shape_.kind && shape.size == shape_.size && friction == friction_ &&
                    (grasp_in_object.translation() - key_.translation()).norm() <= 1e-3 &&
                    Eigen::AngleAxisd(key_.linear().transpose() * grasp_in_object.linear()).angle() <= 0.02;
  if (!same) {
    depth_ = holdDepth(shape, grasp_in_object, friction);
    shape_ = shape;
    key_ = grasp_in_object;
    friction_ = friction;
    valid_ = true;
  }
  return depth_;
}

FingerFit fingerFit(const Isometry& tcp, const Isometry& object, const Isometry& grasp, const io::ObjectShape& shape,
                    double opening, double finger_half_span) {
  FingerFit f;
  if (!shape.known()) return f;
  const Vector3 grasp_closing = grasp.linear().col(1);
  const double width = io::extentAlong(shape, object.linear().transpose() * grasp_closing);
  f.clearance = std::max(kMinClearance, 0.5 * (opening - width));
  // the object's mid-plane across the fingers: where the grasp puts it (0 for
  // a grasp through the centre), moved by the TCP's lateral error
  f.mid_plane = (object.translation() - grasp.translation()).dot(grasp_closing) +
                (grasp.translation() - tcp.translation()).dot(tcp.linear().col(1));
  // the turn between the fingers and the grasp, about the axes across the closing axis (TCP frame)
  const Eigen::AngleAxisd rel(tcp.linear().transpose() * grasp.linear());
  const Vector3 turn = rel.angle() * rel.axis();
  const double widening = finger_half_span * std::hypot(turn.x(), turn.z());
  f.fit = f.clearance - std::abs(f.mid_plane) - widening;
  const Isometry grasp_in_object = object.inverse() * grasp;
  f.near_face = io::exitDistance(shape, grasp_in_object.translation(), -grasp_in_object.linear().col(2));
  return f;
}

void budgetMotion(FingerFit& f, const Isometry& grasp, const Vector3& velocity, const Vector3& tcp_velocity,
                  double speed_std, double horizon, double significance) {
  if (!(horizon > 0.0) || f.clearance > 1e6) return;  // unknown shape: no fit to budget
  const double noise = significance * std::max(0.0, speed_std);
  const auto beyondNoise = [noise](double v) { return std::copysign(std::max(0.0, std::abs(v) - noise), v); };
  // across the fingers: where the object's mid-plane is by the time the arm knows it (the TCP is
  // where it is; the object has moved on by its own way)
  const double drift = beyondNoise(velocity.dot(grasp.linear().col(1))) * horizon;
  f.fit += std::abs(f.mid_plane) - std::abs(f.mid_plane + drift);
  f.mid_plane += drift;
  // toward the palm (against the approach axis, which points from the palm to the object)
  const Vector3 approach = grasp.linear().col(2);
  const double coming = std::max(0.0, -beyondNoise(velocity.dot(approach)));
  // coming: the gap closes at the speed between the two, the arm's own way in (which takes it as
  // long to undo) adding to the object's, its way back (following the object) taking from it
  f.closing_speed = coming > 0.0 ? std::max(0.0, coming + tcp_velocity.dot(approach)) : 0.0;
  f.lead = f.closing_speed * horizon;
}

double padDepth(const FingerFit& f, double along, double pad_reach) { return along + pad_reach + f.near_face; }

namespace {
// the pads reach `wanted` into the object, or half what the grasp itself gives where that is less
bool padsReach(const FingerFit& f, double along, double pad_reach, double wanted) {
  return padDepth(f, along, pad_reach) >= std::min(wanted, 0.5 * (f.near_face + pad_reach));
}
}  // namespace

bool deepEnough(const FingerFit& f, double along, double pad_reach, double grip_depth) {
  if (f.near_face > 1e6) return true;  // unknown shape: nothing to tell
  return padsReach(f, along, pad_reach, grip_depth);
}

bool holdsWhenClosed(const FingerFit& f, double along, double pad_reach) {
  if (f.near_face > 1e6 || !(f.hold_depth > 0.0)) return true;
  return padsReach(f, along, pad_reach, f.hold_depth);
}

double funnelStandoff(const FingerFit& f, double max_standoff, double margin) {
  const double enclosed = margin > 0.0 ? std::clamp(f.fit / (margin * f.clearance), 0.0, 1.0) : (f.fit > 0.0 ? 1.0 : 0.0);
  return max_standoff * (1.0 - enclosed) + f.lead;
}

double GraspFunnel::clearOfFace(const FingerFit& f, double pad_reach) const {
  if (mouth_clearance < 0.0 || !(f.near_face > 0.0) || f.near_face > 1e6) return -1.0;
  return f.near_face + pad_reach + mouth_clearance;
}

double GraspFunnel::mouth(const FingerFit& f, double pad_reach) const {
  const double clear = clearOfFace(f, pad_reach);
  return clear < 0.0 ? max_standoff : std::min(max_standoff, clear);
}

double GraspFunnel::lineUp(const FingerFit& f, double pad_reach) const {
  if (!(f.lead > 0.0)) return max_standoff;
  const double clear = clearOfFace(f, pad_reach);
  return clear < 0.0 ? max_standoff + f.lead : std::max(max_standoff, clear + f.lead);
}

GraspFunnel::Slide GraspFunnel::step(double standoff, double rate, double goal, double time, double extra_speed) {
  Slide s = profile(standoff, rate, goal, time, goal > standoff ? std::max(0.0, extra_speed) : 0.0);
  if (!feed_forward) s.rate = s.acceleration = 0.0;
  return s;
}

GraspFunnel::Slide GraspFunnel::profile(double standoff, double rate, double goal, double time, double extra_speed) {
  const double speed = this->speed + extra_speed;
  const double dt = std::max(0.0, time - last_time);
  last_time = time;
  Slide s;
  const double gap = goal - standoff;
  if (acceleration <= 0.0) {  // first order: at `speed` straight to the goal
    const double reach = speed * dt;
    s.standoff = standoff + std::clamp(gap, -reach, reach);
    s.rate = dt > 0.0 ? (s.standoff - standoff) / dt : 0.0;
    return s;
  }
  if (dt <= 0.0) {
    s.standoff = standoff;
    s.rate = rate;
    return s;
  }
  // the fastest rate after which the rest of the way can still be braked at `acceleration`
  // (v^2 <= 2 a (|gap| - v dt): the discrete braking curve, which does not pass the goal;
  // a goal that moved nearer than the braking distance is passed and come back to), capped
  // at `speed`
  const double a_dt = acceleration * dt;
  if (std::abs(gap) < 1e-9 && std::abs(rate) <= a_dt) {
    // there, at rest. No acceleration: the caller sends nothing more once the slide
    // rests, so an acceleration reported now would be fed forward for good
    s.standoff = goal;
    return s;
  }
  const double brake = -a_dt + std::sqrt(a_dt * a_dt + 2.0 * acceleration * std::abs(gap));
  const double wanted = std::copysign(std::min(speed, brake), gap);
  s.rate = std::clamp(wanted, rate - a_dt, rate + a_dt);
  s.standoff = standoff + s.rate * dt;
  s.acceleration = (s.rate - rate) / dt;
  return s;
}

}  // namespace handover::fsm
