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
  return io::signedDistance(primitiveShapeOf(obj), p);
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
