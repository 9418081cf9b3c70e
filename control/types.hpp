// Fixed-size types shared by the controller. Spatial 6-vectors are ordered
// [linear; angular] everywhere, as in the paper (alpha = [Pdot; omega]).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace handover::control {

constexpr int kArmDofs = 7;  ///< Panda arm joints (fingers are not in the model's dofs)
constexpr int kObjDofs = 6;  ///< observed object's floating-base acceleration
constexpr int kNumVars = kArmDofs + kObjDofs;  ///< QP variables chi = [qddot (7); alphadot_obs (6)]

using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Vector7 = Eigen::Matrix<double, 7, 1>;
using Matrix3 = Eigen::Matrix3d;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Matrix7 = Eigen::Matrix<double, 7, 7>;
using Matrix3x7 = Eigen::Matrix<double, 3, 7>;
using Matrix6x7 = Eigen::Matrix<double, 6, 7>;
using Quaternion = Eigen::Quaterniond;
using Isometry = Eigen::Isometry3d;

}  // namespace handover::control
