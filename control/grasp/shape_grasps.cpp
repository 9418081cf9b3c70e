#include "control/grasp/shape_grasps.hpp"

#include <algorithm>
#include <cmath>

namespace handover::control::grasp {

namespace {

// a grasp whose approach axis makes `elevation` with the horizontal, coming
// down from above for elevation > 0, fingers closing horizontally (along y),
// TCP at `height` on the axis, free about the object's z axis
GraspSpec aroundZ(double elevation, double height) {
  GraspSpec s;
  s.placement.translation() = Vector3(0.0, 0.0, height);
  // side grasp (pi/2 about y: approach along +x), then tilted down about the fingers' axis
  s.placement.linear() = Eigen::AngleAxisd(M_PI / 2 + elevation, Vector3::UnitY()).toRotationMatrix();
  s.has_free_axis = true;
  s.free_axis = Vector3::UnitZ();
  return s;
}

// side and 45 degrees through the centre; top with the TCP `top_height` up the axis
void addRoundFamilies(double top_height, std::vector<GraspSpec>& out) {
  out.push_back(aroundZ(0.0, 0.0));
  out.push_back(aroundZ(M_PI / 4, 0.0));
  out.push_back(aroundZ(M_PI / 2, top_height));
}

void addBoxFamilies(const Vector3& edges, const ShapeGraspOptions& o, std::vector<GraspSpec>& out) {
  const double fits = o.max_opening - o.opening_margin;
  for (int across = 0; across < 3; ++across) {
    if (edges[across] > fits) continue;
    for (int along = 0; along < 3; ++along) {
      if (along == across) continue;
      for (double side : {1.0, -1.0}) {
        // approach toward the centre from the `side` face of axis `along`
        const Vector3 z = -side * Vector3::Unit(along);
        const Vector3 y = Vector3::Unit(across);
        GraspSpec s;
        s.placement.linear().col(0) = y.cross(z);
        s.placement.linear().col(1) = y;
        s.placement.linear().col(2) = z;
        const double half = 0.5 * edges[along];
        const Vector3 in = side * std::max(0.0, half - o.depth) * Vector3::Unit(along);
        s.placement.translation() = in;
        out.push_back(s);
        // and toward either end of the third edge, where a hand holding the middle leaves room
        const int third = 3 - across - along;
        const double end = 0.5 * edges[third] - o.end_inset;
        if (end < o.end_inset) continue;
        for (double toward : {1.0, -1.0}) {
          s.placement.translation() = in + toward * end * Vector3::Unit(third);
          out.push_back(s);
        }
      }
    }
  }
}

}  // namespace

std::vector<GraspSpec> shapeGraspSpecs(PrimitiveShape shape, const std::vector<double>& size,
                                       const ShapeGraspOptions& options) {
  std::vector<GraspSpec> out;
  const double fits = options.max_opening - options.opening_margin;
  switch (shape) {
    case PrimitiveShape::kCylinder:
      if (size.size() == 2 && 2.0 * size[0] <= fits) addRoundFamilies(std::max(0.0, 0.5 * size[1] - options.depth), out);
      break;
    case PrimitiveShape::kSphere:
      if (size.size() == 1 && 2.0 * size[0] <= fits) addRoundFamilies(0.0, out);
      break;
    case PrimitiveShape::kBox:
      if (size.size() == 3) addBoxFamilies(Vector3(size[0], size[1], size[2]), options, out);
      break;
  }
  return out;
}

}  // namespace handover::control::grasp
