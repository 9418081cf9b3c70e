// The grasp families a primitive shape implies, for objects that declare no
// grasp of their own (or to add to the declared ones). The object frame has
// its origin at the shape's centre, as in the scenes: a cylinder's axis is
// its z, a box's edges run along x, y, z.
//
// - cylinder: a side grasp and a 45-degree grasp from above through the
//   centre, and a top grasp `depth` below the top face, each across the
//   diameter and free about the axis (when the diameter fits);
// - sphere: the same three directions through the centre, free about z;
// - box: for every axis the fingers can close across (edge <= the opening),
//   an approach along each of the two other axes, from both sides (the
//   half-turn twin covers the finger flip), the TCP `depth` inside the face,
//   at the middle of the third edge and, where that edge is long enough,
//   `end_inset` from either of its ends: a person holds a box anywhere, often
//   by its middle, and the free end is what a receiver takes (a tall box held
//   high by its middle: the side grasps at the middle put the palm in the
//   person's hand and the top grasp was out of reach).
// Frames and conventions as grasp_candidates.hpp. Units: m. Allocates (start-up).
#pragma once

#include <vector>

#include "control/grasp/grasp_candidates.hpp"

namespace handover::control::grasp {

enum class PrimitiveShape { kCylinder, kBox, kSphere };

struct ShapeGraspOptions {
  double max_opening = 0.08;  ///< m, the gripper's full opening
  double opening_margin = 0.01;  ///< m, kept between the object and the open fingers
  double depth = 0.02;        ///< m, how far inside a box face or a cylinder's top the TCP goes (capped at the centre)
  /// m, a box grasp toward an end keeps the TCP this far from it (a finger's
  /// half width and the sensing error); only edges of at least 4 end_insets
  /// get such grasps
  double end_inset = 0.025;
};

/// Grasp specs of a shape. `size` as in scenario files: cylinder [radius, height],
/// box [x, y, z] full edges, sphere [radius]. Empty when nothing fits the gripper.
std::vector<GraspSpec> shapeGraspSpecs(PrimitiveShape shape, const std::vector<double>& size,
                                       const ShapeGraspOptions& options = ShapeGraspOptions());

}  // namespace handover::control::grasp
