// Where a given object sits in the receiver's hand, from its shape.
//
// params.object_in_hand places the object's centre a fixed height above the
// receiver's grip point (5 cm: a ball or a bottle rests on the palm with its
// surface 1-3 cm above it). A flat object (a phone, a deck of cards, a remote
// 2 cm thick) placed the same way floats with its underside 4 cm above the
// grip point: beyond the 3 cm within which a person closes their hand on an
// object (the scenario contract's object_in_reach), so nobody took it and the
// give timed out. Lowered instead until the object's lowest point is `seat`
// above the grip point; never raised.
//
// Frames: the hand frame (grip point origin, z up); the shape in the object
// frame (interfaces/object_shape.hpp). Units: m. Real-time safe.
#pragma once

#include <algorithm>

#include "fsm/handover/handover_io.hpp"

namespace handover::fsm {

/// `object_in_hand` with its height above the grip point at most the object's
/// extent below its centre (along the hand's z) plus `seat`. Unchanged for an
/// unknown shape or a non-positive seat.
inline Isometry seatedInHand(const Isometry& object_in_hand, const io::ObjectShape& shape, double seat) {
  if (!shape.known() || !(seat > 0.0)) return object_in_hand;
  const Vector3 up_in_object = object_in_hand.linear().transpose() * Vector3::UnitZ();
  const double below_centre = 0.5 * io::extentAlong(shape, up_in_object);
  Isometry seated = object_in_hand;
  seated.translation().z() = std::min(object_in_hand.translation().z(), below_centre + seat);
  return seated;
}

}  // namespace handover::fsm
