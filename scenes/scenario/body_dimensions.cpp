#include "scenes/scenario/body_dimensions.hpp"

#include <cmath>

namespace handover::scenario {

BodyDimensions bodyDimensionsFromHeight(double height) {
  BodyDimensions b;
  b.height = height;
  b.upper_arm = 0.205 * height;
  b.forearm = (0.270 - 0.108) * height;
  b.wrist_to_grip = 0.043 * height;
  b.shoulder_height = 0.818 * height;
  b.shoulder_offset = 0.100 * height;
  b.hip_height = 0.53 * height;
  b.torso_top = 0.81 * height;
  b.head_centre = 0.93 * height;
  b.head_radius = 0.06 * height;
  b.hand_length = 0.108 * height;
  return b;
}

HangingArm freeArmInTorso(const BodyDimensions& body, HandSide handing) {
  // the torso frame's +y is the person's left: a right hand leaves the left arm free
  const double s = handing == HandSide::Right ? 1.0 : -1.0;
  const double y = s * (0.5 * body.torso_width + body.upper_arm_radius);
  HangingArm a;
  a.shoulder = Eigen::Vector3d(0.0, y, body.shoulder_height);
  a.elbow = Eigen::Vector3d(0.0, y, body.shoulder_height - body.upper_arm);
  const double fingertip = a.elbow.z() - body.forearm - body.hand_length;
  a.tip = Eigen::Vector3d(0.0, y, fingertip + body.forearm_radius);
  return a;
}

Eigen::Vector3d shoulderPosition(const BodyDimensions& body, const Eigen::Vector2d& stand_xy,
                                 double yaw, HandSide side) {
  // the person's right is the facing direction turned by -90 deg
  const Eigen::Vector2d right(std::sin(yaw), -std::cos(yaw));
  const double s = side == HandSide::Right ? 1.0 : -1.0;
  const Eigen::Vector2d xy = stand_xy + s * body.shoulder_offset * right;
  return {xy.x(), xy.y(), kFloorZ + body.shoulder_height};
}

}  // namespace handover::scenario
