#include "control/grasp/palm_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace handover::control::grasp {

namespace {

constexpr int kSamples = 24;  // per axis of the object's bounding box: 1/24 of its size apart
constexpr double kFingerHalfFace = 0.01;  // m, half a finger's face across the closing axis (Panda)

}  // namespace

double palmShift(const io::ObjectShape& shape, const Isometry& grasp_in_object, const PalmGeometry& palm) {
  if (!shape.known()) return 0.0;
  // the shape's bounding box in its own frame, sampled; the points inside the shape count
  const Vector3 half(0.5 * io::extentAlong(shape, Vector3::UnitX()), 0.5 * io::extentAlong(shape, Vector3::UnitY()),
                     0.5 * io::extentAlong(shape, Vector3::UnitZ()));
  const Isometry object_in_grasp = grasp_in_object.inverse();
  const double reach_x = palm.half_width + palm.clearance, reach_y = palm.half_length + palm.clearance;
  // over the object's points under the palm: the one nearest the gripper along the approach axis
  // (smallest grasp z); and where the object begins along the TCP's closing line (|x| within a
  // finger's half face): moved back past that, nothing would lie between the fingers
  double nearest = std::numeric_limits<double>::infinity();
  double nearest_on_closing_line = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= kSamples; ++i) {
    for (int j = 0; j <= kSamples; ++j) {
      for (int k = 0; k <= kSamples; ++k) {
        const Vector3 p_obj(half.x() * (2.0 * i / kSamples - 1.0), half.y() * (2.0 * j / kSamples - 1.0),
                            half.z() * (2.0 * k / kSamples - 1.0));
        if (io::signedDistance(shape, p_obj) > 1e-12) continue;
        const Vector3 p = object_in_grasp * p_obj;
        if (std::abs(p.x()) <= reach_x && std::abs(p.y()) <= reach_y) nearest = std::min(nearest, p.z());
        if (std::abs(p.x()) <= kFingerHalfFace) nearest_on_closing_line = std::min(nearest_on_closing_line, p.z());
      }
    }
  }
  if (!std::isfinite(nearest)) return 0.0;
  const double shift = std::max(0.0, palm.clearance - palm.depth - nearest);
  // moved back by `shift`, the TCP's line lies at grasp z = -shift: the object must still reach it
  if (shift > 0.0 && nearest_on_closing_line > -shift) return 0.0;
  return shift;
}

Isometry fitToPalm(const io::ObjectShape& shape, const Isometry& grasp_in_object, const PalmGeometry& palm) {
  return grasp_in_object * Eigen::Translation3d(0.0, 0.0, -palmShift(shape, grasp_in_object, palm));
}

}  // namespace handover::control::grasp
