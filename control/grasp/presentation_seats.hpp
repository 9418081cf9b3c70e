// Where a given object can sit in the receiver's hand: the seats the robot
// may present it at, for the presentation selector (runtime/grasp_planning)
// to choose among by reach.
//
// The declared seat (config/fsm.yaml params.object_in_hand: the object's
// centre 5 cm above the grip point) ignores the object and the gripper: a
// ball held from the side puts the gripper's body on the palm (the
// hand-gripper clearance then held the TCP 2-4 cm short and the ball out of
// the person's reach until they gave up), and a tall bottle held from the top
// lifts the TCP out of the arm's reach when the hand is high. A seat here is
// an object position in the hand frame, its rotation the declared one, where
//   - the grip point (hand origin) is inside the object or within `reach` of
//     its surface: the object is in the hand,
//   - the object's centre is not below the grip point: the hand is under or
//     around it, bearing its weight, and
//   - every gripper capsule, the object held by the declared grasp, keeps
//     `clearance` from the hand's box: the robot can get there without its
//     collision constraint holding it off.
// Found on a grid (`step`) within `range` of the grip point. The declared seat
// alone when it is clear (on the grid); else, best first, the seat nearest
// the declared one and the one with the lowest TCP (a high hand), at least
// `step` apart; empty when none is clear.
//
// Frames: the hand (grip point) frame; capsules in the TCP frame. Units: m.
// Allocates; start-up only (a few ms).
#pragma once

#include <vector>

#include "control/grasp/clearance.hpp"
#include "interfaces/object_shape.hpp"

namespace handover::control::grasp {

struct SeatGeometry {
  io::ObjectShape object;                          ///< the object's shape, its own frame
  Isometry object_in_hand = Isometry::Identity();  ///< the declared seat
  Isometry tcp_in_object = Isometry::Identity();   ///< the grasp the robot holds it by
  std::vector<ObstacleCapsule> gripper_in_tcp;     ///< the gripper's capsules, TCP frame
  Isometry hand_box_in_hand = Isometry::Identity();///< the person's hand box centre
  Vector3 hand_box_size = Vector3(0.09, 0.08, 0.03);  ///< its full edges
};

struct SeatOptions {
  double reach = 0.025;     ///< m, the grip point at most this far outside the object
  double clearance = 0.01;  ///< m, gripper capsules to the hand box
  double step = 0.01;       ///< m, grid spacing
  double range = 0.15;      ///< m, grid half-width around the grip point
  int max_seats = 2;
};

/// Object poses in the hand frame (object_in_hand), best first.
std::vector<Isometry> presentationSeats(const SeatGeometry& geometry, const SeatOptions& options);

/// Smallest distance (m) between the segment [a, b] and the box of full edges
/// `size` centred at `box` (0 when they meet).
double segmentBoxDistance(const Vector3& a, const Vector3& b, const Isometry& box, const Vector3& size);

/// The model's gripper capsules (roles kGripper, kFingertip) in the frame `frame`.
std::vector<ObstacleCapsule> gripperCapsulesIn(const Model& model, const std::string& frame);

}  // namespace handover::control::grasp
