#include "scenes/scenario/object_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace handover::scenario {

io::ObjectShape primitiveShapeOf(const ObjectSpec& obj) {
  io::ObjectShape s;
  for (std::size_t i = 0; i < obj.size.size() && i < 3; ++i) s.size[static_cast<int>(i)] = obj.size[i];
  switch (obj.shape) {
    case Shape::Sphere: s.kind = io::ObjectShape::Kind::kSphere; break;
    case Shape::Cylinder: s.kind = io::ObjectShape::Kind::kCylinder; break;
    case Shape::Box: s.kind = io::ObjectShape::Kind::kBox; break;
  }
  return s;
}

double objectExtent(const ObjectSpec& obj, const Eigen::Vector3d& u) { return io::extentAlong(primitiveShapeOf(obj), u); }

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
