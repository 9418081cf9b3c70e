// Narrow-phase distance between two convex primitives, computed by FCL 0.7.
//
// This header hides FCL on purpose: every FCL include lives in
// shape_distance.cpp (FCL headers cost seconds of compile time per file).
//
// Shapes are "cores": a robot or person capsule enters as its bare segment
// (radius 0), and the caller subtracts the radii. The distance between cores
// stays positive and its witness points and normal stay well defined until
// the segments themselves meet, long after the capsule surfaces touched.
// Frames: a shape's canonical frame has its centre at the origin; a segment
// runs along z from -length/2 to +length/2; a box has full edge lengths
// `size` along x, y, z. Units: m.
#pragma once

#include <memory>
#include <vector>

#include "control/types.hpp"

namespace handover::control {

/// One primitive of the collision scene.
struct ShapeSpec {
  enum class Kind { kSegment, kBox };
  Kind kind = Kind::kSegment;
  double length = 0.0;             ///< segment: full length along z, m (>= 0)
  Vector3 size = Vector3::Zero();  ///< box: full edge lengths, m (> 0)
};

/// Result of one distance query, world frame.
struct ShapeDistanceResult {
  double distance = 0.0;            ///< m, >= 0; 0 when the shapes overlap
  Vector3 p1 = Vector3::Zero();     ///< closest point on shape 1, world, m
  Vector3 p2 = Vector3::Zero();     ///< closest point on shape 2, world, m
  bool separated = false;           ///< false: the shapes overlap, p1/p2 unreliable
};

/// Owns the FCL geometries of a scene, built once (allocates); queries are
/// real-time safe (no allocation, no exceptions).
class ShapeDistance {
 public:
  explicit ShapeDistance(const std::vector<ShapeSpec>& shapes);
  ~ShapeDistance();
  ShapeDistance(ShapeDistance&&) noexcept;
  ShapeDistance& operator=(ShapeDistance&&) noexcept;

  int numShapes() const;
  /// Changes the length of segment `shape` (e.g. a person's forearm). RT safe.
  void setSegmentLength(int shape, double length);
  double segmentLength(int shape) const;

  /// Distance between shape i at canonical pose Xi and shape j at Xj (world).
  /// Segment-segment is FCL's analytic solution; segment-box is FCL's GJK
  /// (GST_INDEP, tolerance 1e-9) polished to machine precision. RT safe.
  void compute(int i, const Isometry& Xi, int j, const Isometry& Xj, ShapeDistanceResult& out) const;

 private:
  void segmentBox(int seg, const Isometry& Xs, int box, const Isometry& Xb, double& d, Vector3& ps, Vector3& pb) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace handover::control
