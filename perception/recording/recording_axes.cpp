#include "perception/recording/recording_axes.hpp"

#include <cmath>

namespace handover::perception::recording {

Eigen::Matrix3d upRotation(const SignedAxis& up) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  if (up.index == 1) R = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  if (up.index == 0) R = Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  // a downward axis: half a turn about a horizontal axis of the result
  if (up.sign < 0) R = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix() * R;
  return R;
}

Eigen::Matrix3d boneAxes(const SignedAxis& long_axis) {
  Eigen::Matrix3d B;
  B.col(2) = long_axis.vector();
  B.col(0) = Eigen::Vector3d::Unit((long_axis.index + 1) % 3);
  B.col(1) = B.col(2).cross(B.col(0));
  return B;
}

Eigen::Matrix3d handAxes(const SignedAxis& long_axis, const SignedAxis& back_axis) {
  Eigen::Matrix3d B;
  B.col(0) = -long_axis.vector();
  B.col(2) = back_axis.vector();
  B.col(1) = B.col(2).cross(B.col(0));
  return B;
}

Eigen::Isometry3d mirrored(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix3d S = Eigen::Vector3d(1.0, -1.0, 1.0).asDiagonal();
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = S * pose.linear() * S;
  out.translation() = S * pose.translation();
  return out;
}

}  // namespace handover::perception::recording
