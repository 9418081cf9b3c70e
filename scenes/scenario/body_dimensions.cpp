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
  return b;
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
