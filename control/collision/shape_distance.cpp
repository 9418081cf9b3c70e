// The only translation unit that includes FCL (compile time, see the header).
#include "control/collision/shape_distance.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/narrowphase/detail/gjk_solver_indep.h>

#include <algorithm>

#include "config/input_error.hpp"

namespace handover::control {

// The GJK solver is called directly rather than through fcl::distance()
// (no DistanceResult to clear, no dispatch table). GJK of a segment against a
// box is fast (~0.7 us) but can stall up to 1e-4 m short of the distance in
// degenerate cases, so its witness is polished exactly afterwards (see
// segmentBox). GJK against a rounded capsule converges better but is 3-4x
// slower, because a round cap needs many iterations to reach 1e-9.
struct ShapeDistance::Impl {
  std::vector<std::unique_ptr<fcl::Capsuled>> segments;  // bare (radius 0); null for boxes
  std::vector<std::unique_ptr<fcl::Boxd>> boxes;         // null for segments
  std::vector<ShapeSpec> specs;
  fcl::detail::GJKSolver_indep<double> solver;
};

ShapeDistance::ShapeDistance(const std::vector<ShapeSpec>& shapes) : impl_(std::make_unique<Impl>()) {
  impl_->specs = shapes;
  impl_->segments.resize(shapes.size());
  impl_->boxes.resize(shapes.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const ShapeSpec& s = shapes[i];
    if (s.kind == ShapeSpec::Kind::kSegment) {
      if (!(s.length >= 0.0)) throw InputError("collision shape " + std::to_string(i) + ": segment length must be >= 0");
      // radius 0: the caller owns the radii (see header)
      impl_->segments[i] = std::make_unique<fcl::Capsuled>(0.0, s.length);
    } else {
      if (!(s.size.minCoeff() > 0.0))
        throw InputError("collision shape " + std::to_string(i) + ": box edges must be > 0");
      impl_->boxes[i] = std::make_unique<fcl::Boxd>(s.size);
    }
  }
  // design notes 6: GST_INDEP with tolerance 1e-9; unsigned distances only
  impl_->solver.gjk_tolerance = 1e-9;
  impl_->solver.gjk_max_iterations = 128;  // bounded work; the polish fixes a stalled answer
  impl_->solver.enable_cached_guess = false;
}

ShapeDistance::~ShapeDistance() = default;
ShapeDistance::ShapeDistance(ShapeDistance&&) noexcept = default;
ShapeDistance& ShapeDistance::operator=(ShapeDistance&&) noexcept = default;

int ShapeDistance::numShapes() const { return static_cast<int>(impl_->specs.size()); }

void ShapeDistance::setSegmentLength(int shape, double length) {
  if (!impl_->segments[shape]) return;
  impl_->segments[shape]->lz = length;
  impl_->specs[shape].length = length;
}

double ShapeDistance::segmentLength(int shape) const { return impl_->specs[shape].length; }

void ShapeDistance::segmentBox(int seg, const Isometry& Xs, int box, const Isometry& Xb, double& d, Vector3& ps,
                               Vector3& pb) const {
  const Impl& m = *impl_;
  if (!m.solver.shapeDistance(*m.segments[seg], Xs, *m.boxes[box], Xb, &d, &ps, &pb) || !(d > 0.0)) {
    d = -1.0;  // the segment enters the box
    return;
  }
  {
    // polish: in the box frame the squared gap along the segment,
    // f(t) = sum_k max(|p_k(t)| - h_k, 0)^2, is convex and piecewise
    // quadratic; Newton steps from GJK's point land on the minimum of the
    // right piece, usually in one step
    const double half = 0.5 * m.segments[seg]->lz;
    const Isometry Xbi = Xb.inverse(Eigen::Isometry);
    const Vector3 c = Xbi * Xs.translation(), u = Xbi.linear() * Xs.linear().col(2);
    const Vector3 h = 0.5 * m.boxes[box]->side;
    double t = std::clamp(u.dot(Xbi * ps - c), -half, half);
    // half the derivative of f, and the gap itself
    auto slope = [&](double tt, double& den) {
      const Vector3 p = c + tt * u;
      double num = 0.0;
      den = 0.0;
      for (int k = 0; k < 3; ++k) {
        if (std::abs(p[k]) > h[k]) {
          num += u[k] * (p[k] - std::copysign(h[k], p[k]));
          den += u[k] * u[k];
        }
      }
      return num;
    };
    auto gap = [&](double tt) {
      const Vector3 p = c + tt * u;
      return (p - p.cwiseMax(-h).cwiseMin(h)).norm();
    };
    double den = 0.0;
    for (int it = 0; it < 6; ++it) {
      const double num = slope(t, den);
      if (den < 1e-300) break;
      const double t_new = std::clamp(t - num / den, -half, half);
      if (std::abs(t_new - t) < 1e-15) break;
      t = t_new;
    }
    // f is C1 and convex: optimal where the slope vanishes or points out of the segment
    const double g = slope(t, den);
    const bool optimal = std::abs(g) < 1e-12 || (t <= -half && g >= 0.0) || (t >= half && g <= 0.0);
    if (!optimal) {
      // Newton cycled between pieces (rare): golden-section search instead
      double lo = -half, hi = half;
      for (int it = 0; it < 80; ++it) {
        const double m1 = hi - 0.618033988749895 * (hi - lo), m2 = lo + 0.618033988749895 * (hi - lo);
        if (gap(m1) < gap(m2)) {
          hi = m2;
        } else {
          lo = m1;
        }
      }
      t = 0.5 * (lo + hi);
    }
    const Vector3 p = c + t * u;
    ps = Xb * p;
    pb = Xb * p.cwiseMax(-h).cwiseMin(h);
    d = (ps - pb).norm();
  }
}

void ShapeDistance::compute(int i, const Isometry& Xi, int j, const Isometry& Xj, ShapeDistanceResult& out) const {
  const Impl& m = *impl_;
  double d = -1.0;
  Vector3 p1 = Vector3::Zero(), p2 = Vector3::Zero();
  // witness points come back in the world frame
  if (m.segments[i] && m.segments[j]) {
    m.solver.shapeDistance(*m.segments[i], Xi, *m.segments[j], Xj, &d, &p1, &p2);  // analytic
  } else if (m.segments[i] && m.boxes[j]) {
    segmentBox(i, Xi, j, Xj, d, p1, p2);
  } else if (m.boxes[i] && m.segments[j]) {
    segmentBox(j, Xj, i, Xi, d, p2, p1);
  } else {
    m.solver.shapeDistance(*m.boxes[i], Xi, *m.boxes[j], Xj, &d, &p1, &p2);
  }
  // GJK reports -1 (and no points) when the shapes overlap; segments report 0
  out.separated = d > 0.0;
  out.distance = out.separated ? d : 0.0;
  out.p1 = p1;
  out.p2 = p2;
}

}  // namespace handover::control
