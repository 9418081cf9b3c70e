// Body dimensions of the simulated person, scaled from the stature.
//
// World frame (design notes 1): z up, table top z = 0, floor z = -0.75,
// x from the robot toward the person. Lengths in m, angles in rad.
//
// Proportions (fractions of the stature H):
//   upper arm (shoulder-elbow)    0.205 H  facts file: 0.361/1.759 and 0.332/1.618 both give 0.205
//   forearm + hand (elbow-tip)    0.270 H  facts file: 0.483/1.759 = 0.275, 0.428/1.618 = 0.265
//   hand length (wrist-tip)       0.108 H  (approx) so forearm (elbow-wrist) = 0.162 H
//   wrist to grip point           0.043 H  (approx) the palm centre, 0.4 of the hand length
//   shoulder height above floor   0.818 H  (approx) usual anthropometric ratio
//   shoulder joint off midline    0.100 H  (approx) a little inside half the biacromial breadth
// Trunk (the simulated person's torso body, scenes/handover_scene.xml; heights above the floor):
//   hip (legs box top)            0.530 H  torso box from the hip to 0.810 H
//   head centre                   0.930 H  head sphere radius 0.06 H
//   torso box depth x width       0.22 x 0.38 m; legs box 0.18 x 0.32 m (fixed, not scaled)
// The other arm (not handing, not tracked; freeArmInTorso): hangs relaxed beside the torso,
//   upper arm 0.205 H, forearm + hand 0.270 H (facts file), capsule radii 0.045 / 0.035 m
//   (the simulated handing arm's, fixed), its axis just outside the torso box.
// A 1.75 m person: upper arm 0.359, forearm 0.284, wrist-grip 0.075, reach
// (shoulder to grip point, arm straight) 0.718, shoulder 0.68 above the table.
// All functions are pure and real-time safe.
#pragma once

#include <Eigen/Core>

namespace handover::scenario {

constexpr double kFloorZ = -0.75;  ///< m, floor height in the world (table top is z = 0)

enum class HandSide { Right, Left };

struct BodyDimensions {
  double height = 1.75;             ///< stature, m
  double upper_arm = 0.0;           ///< shoulder to elbow, m
  double forearm = 0.0;             ///< elbow to wrist, m
  double wrist_to_grip = 0.0;       ///< wrist to the grip point (palm centre), m
  double shoulder_height = 0.0;     ///< shoulder joint above the floor, m
  double shoulder_offset = 0.0;     ///< shoulder joint sideways from the body midline, m
  // trunk, in the torso frame (origin on the floor under the body centre, x forward, z up)
  double hip_height = 0.0;          ///< top of the legs box, bottom of the torso box, m
  double torso_top = 0.0;           ///< top of the torso box, m
  double torso_depth = 0.22;        ///< torso box along x (front to back), m
  double torso_width = 0.38;        ///< torso box along y (side to side), m
  double legs_depth = 0.18;         ///< legs box along x, m
  double legs_width = 0.32;         ///< legs box along y, m
  double head_centre = 0.0;         ///< head sphere centre above the floor, m
  double head_radius = 0.0;         ///< m
  double hand_length = 0.0;         ///< wrist to fingertip, m
  double upper_arm_radius = 0.045;  ///< m, the simulated upper arms' capsule radius (not scaled)
  double forearm_radius = 0.035;    ///< m, the simulated forearms' (and hanging hand's) radius (not scaled)

  /// Elbow to grip point, m: the second link of the two-link arm.
  double elbowToGrip() const { return forearm + wrist_to_grip; }
  /// Shoulder to grip point with the arm straight, m.
  double reach() const { return upper_arm + elbowToGrip(); }
};

/// Dimensions scaled from the stature `height` (m).
BodyDimensions bodyDimensionsFromHeight(double height);

/// Shoulder joint of the arm on `side`, world frame, m. The person stands at
/// `stand_xy` (floor point under the body centre) facing `yaw` (rad about z;
/// yaw = pi faces the robot from +x).
Eigen::Vector3d shoulderPosition(const BodyDimensions& body, const Eigen::Vector2d& stand_xy,
                                 double yaw, HandSide side);

/// The arm the person does not hand with: nobody tracks it, so the simulated
/// person and the controller both take it as hanging relaxed beside the
/// torso. Capsule cores in the torso frame (origin on the floor under the body
/// centre, x forward, y to the person's left, z up), m: the upper arm from
/// `shoulder` to `elbow` (radius upper_arm_radius), the forearm and hand from
/// `elbow` to `tip` (radius forearm_radius; the fingertips are at tip minus
/// that radius in z). On the side opposite `handing`.
struct HangingArm {
  Eigen::Vector3d shoulder = Eigen::Vector3d::Zero();
  Eigen::Vector3d elbow = Eigen::Vector3d::Zero();
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
};
HangingArm freeArmInTorso(const BodyDimensions& body, HandSide handing);

/// Nearest distance (m) from the shoulder that the grip point can sit at
/// without the hand passing through the shoulder.
constexpr double kMinShoulderToGrip = 0.15;

}  // namespace handover::scenario
