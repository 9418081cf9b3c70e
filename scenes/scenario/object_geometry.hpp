// Geometry of the hand-held object in its own frame (cylinder axis z, box and
// sphere centred at the origin; sizes as in ObjectSpec): how wide it is along
// a direction and how far a point is from its surface. Used to check that a
// scenario's grasp and hold poses are physical. Start-up only.
#pragma once

#include <Eigen/Core>

#include "interfaces/object_shape.hpp"
#include "scenes/scenario/scenario.hpp"

namespace handover::scenario {

/// Gripper opening (Panda, both fingers at 0.04 m), m.
constexpr double kGripperOpening = 0.08;

/// The object's primitive shape (io::ObjectShape) for the controller side.
io::ObjectShape primitiveShapeOf(const ObjectSpec& obj);

/// Extent (m) of the object along the unit direction `u` of its frame: the
/// distance between its two supporting planes normal to u.
double objectExtent(const ObjectSpec& obj, const Eigen::Vector3d& u);

/// Width the fingers close on (m): the extent along the grasp frame's y axis.
double objectWidthAcrossFingers(const ObjectSpec& obj);

/// Signed distance (m) from the point `p` (object frame) to the object's
/// surface: negative inside.
double signedDistanceToObject(const ObjectSpec& obj, const Eigen::Vector3d& p);

/// Volume (m^3).
double objectVolume(const ObjectSpec& obj);

}  // namespace handover::scenario
