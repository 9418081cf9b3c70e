#include "scenes/scenario/object_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace handover::scenario {

double objectExtent(const ObjectSpec& obj, const Eigen::Vector3d& u_in) {
  const Eigen::Vector3d u = u_in.normalized();
  switch (obj.shape) {
    case Shape::Sphere: return 2.0 * obj.size[0];
    case Shape::Cylinder: {
      // the disc contributes its diameter scaled by the sine to the axis, the
      // axis its height scaled by the cosine
      const double c = std::min(1.0, std::abs(u.z()));
      return 2.0 * obj.size[0] * std::sqrt(1.0 - c * c) + obj.size[1] * c;
    }
    case Shape::Box:
      return std::abs(u.x()) * obj.size[0] + std::abs(u.y()) * obj.size[1] + std::abs(u.z()) * obj.size[2];
  }
  return 0.0;
}

double objectWidthAcrossFingers(const ObjectSpec& obj) { return objectExtent(obj, obj.grasp.linear().col(1)); }

double signedDistanceToObject(const ObjectSpec& obj, const Eigen::Vector3d& p) {
  switch (obj.shape) {
    case Shape::Sphere: return p.norm() - obj.size[0];
    case Shape::Cylinder: {
      const Eigen::Vector2d d(p.head<2>().norm() - obj.size[0], std::abs(p.z()) - obj.size[1] / 2.0);
      return std::min(d.maxCoeff(), 0.0) + d.cwiseMax(0.0).norm();
    }
    case Shape::Box: {
      const Eigen::Vector3d half(obj.size[0] / 2.0, obj.size[1] / 2.0, obj.size[2] / 2.0);
      const Eigen::Vector3d d = p.cwiseAbs() - half;
      return std::min(d.maxCoeff(), 0.0) + d.cwiseMax(0.0).norm();
    }
  }
  return 0.0;
}

double objectVolume(const ObjectSpec& obj) {
  switch (obj.shape) {
    case Shape::Sphere: return 4.0 / 3.0 * M_PI * std::pow(obj.size[0], 3);
    case Shape::Cylinder: return M_PI * obj.size[0] * obj.size[0] * obj.size[1];
    case Shape::Box: return obj.size[0] * obj.size[1] * obj.size[2];
  }
  return 0.0;
}

}  // namespace handover::scenario
