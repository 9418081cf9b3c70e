// The hand-held object's primitive shape, in the object's own frame: origin at
// the shape's centre, a cylinder's axis along z, a box's edges along x, y, z
// (as in the scenes and the scenario files). Neutral: the scenario checks, the
// collision model's setup, the state machine's grasp funnel and the simulated
// person read it.
// Units: m. Real-time safe (no allocation).
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace handover::io {

struct ObjectShape {
  enum class Kind { kUnknown, kBox, kCylinder, kSphere };
  Kind kind = Kind::kUnknown;
  /// box: full edges [x, y, z]; cylinder: [radius, height, -]; sphere: [radius, -, -]
  Eigen::Vector3d size = Eigen::Vector3d::Zero();

  bool known() const { return kind != Kind::kUnknown; }
};

/// Extent (m) of the shape along the direction `u` of its frame (any length
/// > 0): the distance between its two supporting planes normal to u. 0 when
/// the shape is unknown.
inline double extentAlong(const ObjectShape& s, const Eigen::Vector3d& u_in) {
  const double n = u_in.norm();
  if (!(n > 0.0)) return 0.0;
  const Eigen::Vector3d u = u_in / n;
  switch (s.kind) {
    case ObjectShape::Kind::kSphere: return 2.0 * s.size.x();
    case ObjectShape::Kind::kCylinder: {
      // the disc contributes its diameter scaled by the sine to the axis, the
      // axis its height scaled by the cosine
      const double c = std::min(1.0, std::abs(u.z()));
      return 2.0 * s.size.x() * std::sqrt(1.0 - c * c) + s.size.y() * c;
    }
    case ObjectShape::Kind::kBox: return u.cwiseAbs().dot(s.size);
    case ObjectShape::Kind::kUnknown: break;
  }
  return 0.0;
}

/// Radius (m) of the smallest sphere about the shape's centre that holds it;
/// 0 when the shape is unknown.
inline double boundingRadius(const ObjectShape& s) {
  switch (s.kind) {
    case ObjectShape::Kind::kSphere: return s.size.x();
    case ObjectShape::Kind::kCylinder: return std::hypot(s.size.x(), 0.5 * s.size.y());
    case ObjectShape::Kind::kBox: return 0.5 * s.size.norm();
    case ObjectShape::Kind::kUnknown: break;
  }
  return 0.0;
}

/// Signed distance (m) from the point `p` (object frame) to the shape's
/// surface: negative inside; 0 when the shape is unknown.
inline double signedDistance(const ObjectShape& s, const Eigen::Vector3d& p) {
  switch (s.kind) {
    case ObjectShape::Kind::kSphere: return p.norm() - s.size.x();
    case ObjectShape::Kind::kCylinder: {
      const Eigen::Vector2d d(p.head<2>().norm() - s.size.x(), std::abs(p.z()) - 0.5 * s.size.y());
      return std::min(d.maxCoeff(), 0.0) + d.cwiseMax(0.0).norm();
    }
    case ObjectShape::Kind::kBox: {
      const Eigen::Vector3d d = p.cwiseAbs() - 0.5 * s.size;
      return std::min(d.maxCoeff(), 0.0) + d.cwiseMax(0.0).norm();
    }
    case ObjectShape::Kind::kUnknown: break;
  }
  return 0.0;
}

/// Distance (m, >= 0) from the point `p` (object frame) along the direction
/// `u_in` (object frame, any length > 0) to where the ray leaves the shape:
/// how much of the object lies ahead of p that way. 0 when p is outside, for
/// a zero direction, or when the shape is unknown.
inline double exitDistance(const ObjectShape& s, const Eigen::Vector3d& p, const Eigen::Vector3d& u_in) {
  const double n = u_in.norm();
  if (!(n > 0.0) || !s.known() || signedDistance(s, p) >= 0.0) return 0.0;
  const Eigen::Vector3d u = u_in / n;
  // the ray's exit through the slab |x . a| <= h (a unit, p inside it)
  const auto slab = [&](double pa, double ua, double h) {
    if (std::abs(ua) < 1e-12) return 1e9;
    return ((ua > 0.0 ? h : -h) - pa) / ua;
  };
  double t = 0.0;
  switch (s.kind) {
    case ObjectShape::Kind::kSphere: {
      const double b = p.dot(u), c = p.squaredNorm() - s.size.x() * s.size.x();
      t = -b + std::sqrt(std::max(0.0, b * b - c));
      break;
    }
    case ObjectShape::Kind::kCylinder: {
      // the side: |p_xy + t u_xy| = r; the caps: the slab of half height along z
      const double a = u.head<2>().squaredNorm(), b = p.head<2>().dot(u.head<2>()),
                   c = p.head<2>().squaredNorm() - s.size.x() * s.size.x();
      const double side = a > 1e-12 ? (-b + std::sqrt(std::max(0.0, b * b - a * c))) / a : 1e9;
      t = std::min(side, slab(p.z(), u.z(), 0.5 * s.size.y()));
      break;
    }
    case ObjectShape::Kind::kBox:
      t = std::min({slab(p.x(), u.x(), 0.5 * s.size.x()), slab(p.y(), u.y(), 0.5 * s.size.y()),
                    slab(p.z(), u.z(), 0.5 * s.size.z())});
      break;
    case ObjectShape::Kind::kUnknown: break;
  }
  return std::max(0.0, t);
}

}  // namespace handover::io
