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

FingerFit fingerFit(const Isometry& tcp, const Isometry& object, const Isometry& grasp, const io::ObjectShape& shape,
                    double opening, double finger_half_span) {
  FingerFit f;
  if (!shape.known()) return f;
  const Vector3 grasp_closing = grasp.linear().col(1);
  const double width = io::extentAlong(shape, object.linear().transpose() * grasp_closing);
  f.clearance = std::max(kMinClearance, 0.5 * (opening - width));
  // the object's mid-plane across the fingers: where the grasp puts it (0 for
  // a grasp through the centre), moved by the TCP's lateral error
  const double mid_plane = (object.translation() - grasp.translation()).dot(grasp_closing) +
                           (grasp.translation() - tcp.translation()).dot(tcp.linear().col(1));
  // the turn between the fingers and the grasp, about the axes across the closing axis (TCP frame)
  const Eigen::AngleAxisd rel(tcp.linear().transpose() * grasp.linear());
  const Vector3 turn = rel.angle() * rel.axis();
  const double widening = finger_half_span * std::hypot(turn.x(), turn.z());
  f.fit = f.clearance - std::abs(mid_plane) - widening;
  return f;
}

double funnelStandoff(const FingerFit& f, double max_standoff, double margin) {
  const double enclosed = margin > 0.0 ? std::clamp(f.fit / (margin * f.clearance), 0.0, 1.0) : (f.fit > 0.0 ? 1.0 : 0.0);
  return max_standoff * (1.0 - enclosed);
}

double GraspFunnel::step(double standoff, double goal, double time) {
  const double reach = speed * std::max(0.0, time - last_time);
  last_time = time;
  return standoff + std::clamp(goal - standoff, -reach, reach);
}

}  // namespace handover::fsm
