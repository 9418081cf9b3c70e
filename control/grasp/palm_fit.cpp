#include "control/grasp/palm_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace handover::control::grasp {

namespace {

constexpr int kSamples = 24;  // per axis of the object's bounding box: 1/24 of its size apart
constexpr double kFingerHalfFace = 0.01;  // m, half a finger's face across the closing axis (Panda)

// half extents of the shape's bounding box in its own frame
Vector3 halfExtents(PrimitiveShape shape, const std::vector<double>& size) {
  switch (shape) {
    case PrimitiveShape::kBox: return 0.5 * Vector3(size.at(0), size.at(1), size.at(2));
    case PrimitiveShape::kSphere: return Vector3::Constant(size.at(0));
    case PrimitiveShape::kCylinder: return Vector3(size.at(0), size.at(0), 0.5 * size.at(1));
  }
  return Vector3::Zero();
}

bool inside(PrimitiveShape shape, const std::vector<double>& size, const Vector3& p) {
  switch (shape) {
    case PrimitiveShape::kBox: return true;  // the grid spans the box itself
    case PrimitiveShape::kSphere: return p.norm() <= size.at(0);
    case PrimitiveShape::kCylinder: return p.head<2>().norm() <= size.at(0);
  }
  return false;
}

}  // namespace

double palmShift(PrimitiveShape shape, const std::vector<double>& size, const Isometry& grasp_in_object,
                 const PalmGeometry& palm) {
  const Vector3 half = halfExtents(shape, size);
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
        if (!inside(shape, size, p_obj)) continue;
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

Isometry fitToPalm(PrimitiveShape shape, const std::vector<double>& size, const Isometry& grasp_in_object,
                   const PalmGeometry& palm) {
  return grasp_in_object * Eigen::Translation3d(0.0, 0.0, -palmShift(shape, size, grasp_in_object, palm));
}

}  // namespace handover::control::grasp
