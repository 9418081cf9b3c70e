// The only translation unit that includes FCL (compile time, see the header).
#include "control/collision/shape_distance.hpp"

#include <fcl/narrowphase/distance.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>

#include "config/input_error.hpp"

namespace handover::control {

struct ShapeDistance::Impl {
  std::vector<std::unique_ptr<fcl::CollisionGeometryd>> geometries;
  std::vector<ShapeSpec> specs;
  fcl::DistanceRequestd request;
};

ShapeDistance::ShapeDistance(const std::vector<ShapeSpec>& shapes) : impl_(std::make_unique<Impl>()) {
  impl_->specs = shapes;
  impl_->geometries.reserve(shapes.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const ShapeSpec& s = shapes[i];
    if (s.kind == ShapeSpec::Kind::kSegment) {
      if (!(s.length >= 0.0)) throw InputError("collision shape " + std::to_string(i) + ": segment length must be >= 0");
      // radius 0: the caller owns the radii (see header)
      impl_->geometries.push_back(std::make_unique<fcl::Capsuled>(0.0, s.length));
    } else {
      if (!(s.size.minCoeff() > 0.0))
        throw InputError("collision shape " + std::to_string(i) + ": box edges must be > 0");
      impl_->geometries.push_back(std::make_unique<fcl::Boxd>(s.size));
    }
  }
  // design notes 6: exact enough with GST_INDEP at 1e-9; never signed distances
  impl_->request.enable_nearest_points = true;
  impl_->request.enable_signed_distance = false;
  impl_->request.gjk_solver_type = fcl::GST_INDEP;
  impl_->request.distance_tolerance = 1e-9;
}

ShapeDistance::~ShapeDistance() = default;
ShapeDistance::ShapeDistance(ShapeDistance&&) noexcept = default;
ShapeDistance& ShapeDistance::operator=(ShapeDistance&&) noexcept = default;

int ShapeDistance::numShapes() const { return static_cast<int>(impl_->geometries.size()); }

void ShapeDistance::setSegmentLength(int shape, double length) {
  auto* cap = static_cast<fcl::Capsuled*>(impl_->geometries[shape].get());
  cap->lz = length;
  impl_->specs[shape].length = length;
}

double ShapeDistance::segmentLength(int shape) const { return impl_->specs[shape].length; }

void ShapeDistance::compute(int i, const Isometry& Xi, int j, const Isometry& Xj, ShapeDistanceResult& out) const {
  fcl::DistanceResultd result;
  result.clear();  // design notes 6: a reused result keeps its old minimum otherwise
  fcl::distance(impl_->geometries[i].get(), Xi, impl_->geometries[j].get(), Xj, impl_->request, result);
  if (result.min_distance > 0.0) {
    out.distance = result.min_distance;
    out.p1 = result.nearest_points[0];
    out.p2 = result.nearest_points[1];
    out.separated = true;
  } else {
    // GJK reports -1 when the shapes overlap; segment-segment reports 0
    out.distance = 0.0;
    out.p1 = result.nearest_points[0];
    out.p2 = result.nearest_points[1];
    out.separated = false;
  }
}

}  // namespace handover::control
