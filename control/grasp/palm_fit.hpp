// How deep the gripper can take a grasp: the palm must stay out of the object.
//
// A grasp frame puts the TCP (between the fingertips) at a point of the
// object; the palm lies `depth` behind it along the approach axis (Panda
// hand: 0.0454 m, the length of the fingers to the TCP). A grasp declared
// deeper than that into a part of the object the palm would cover (an angled
// grasp 4.5 cm into a box 10 cm long, a side grasp through the middle of a
// wide box) can never be reached: the fingers' tips or the palm land on the
// object, and the approach stops short until the person gives up. Such a
// grasp is taken as deep as the palm allows: moved back along its approach
// axis until the palm keeps `clearance` from the object, as long as the
// fingers still close across the object there.
//
// Frames: the grasp frame in the object frame (design notes: grasp z = the
// approach axis, fingers close along grasp y); the object frame has its
// origin at the shape's centre (interfaces/object_shape.hpp). Units: m.
// Allocates nothing, but samples the object's volume: start-up only (not RT).
#pragma once

#include "control/types.hpp"
#include "interfaces/object_shape.hpp"

namespace handover::control::grasp {

/// The palm as the gripper presents it to the object: a rectangle across the
/// approach axis, `depth` behind the TCP. Defaults: the Panda hand.
struct PalmGeometry {
  double depth = 0.0454;       ///< m from the TCP back to the palm's face, along the approach axis
  double half_width = 0.025;   ///< m, half its extent along the grasp x (across the fingers' faces)
  double half_length = 0.10;   ///< m, half its extent along the grasp y (the closing axis)
  double clearance = 0.005;    ///< m kept between the palm and the object
};

/// m (>= 0): how far `grasp_in_object` must move back along its approach axis
/// for the palm to keep its clearance from the object; 0 when it already
/// does, or when moving back would leave no object between the fingers (the
/// grasp is then left as it is: it was never one the palm hindered).
/// 0 for an unknown shape.
double palmShift(const io::ObjectShape& shape, const Isometry& grasp_in_object, const PalmGeometry& palm);

/// `grasp_in_object` moved back along its approach axis by palmShift.
Isometry fitToPalm(const io::ObjectShape& shape, const Isometry& grasp_in_object, const PalmGeometry& palm);

}  // namespace handover::control::grasp
