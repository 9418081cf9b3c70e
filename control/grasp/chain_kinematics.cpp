#include "control/grasp/chain_kinematics.hpp"

#include <cmath>

namespace handover::control::grasp {

void chainPoses(const Model& model, const Vector7& q, ChainPoses& poses) {
  poses.oMb[0].setIdentity();
  poses.axis[0].setZero();
  for (int i = 1; i < kNumBodies; ++i) {
    const Isometry& parent = poses.oMb[i - 1];
    const Isometry& joint = model.joint_placements[i - 1];
    const Matrix3 R_joint = parent.linear() * joint.linear();
    poses.axis[i] = R_joint * model.joint_axes[i - 1];
    poses.oMb[i].translation() = parent * joint.translation();
    const Vector3& a = model.joint_axes[i - 1];
    if (a.x() == 0.0 && a.y() == 0.0 && a.z() == 1.0) {
      // the URDF's joints turn about z: R_joint Rz(q) mixes two columns only
      const double c = std::cos(q[i - 1]), s = std::sin(q[i - 1]);
      auto R = poses.oMb[i].linear();
      R.col(0) = c * R_joint.col(0) + s * R_joint.col(1);
      R.col(1) = c * R_joint.col(1) - s * R_joint.col(0);
      R.col(2) = R_joint.col(2);
    } else {
      poses.oMb[i].linear() = R_joint * Eigen::AngleAxisd(q[i - 1], a).toRotationMatrix();
    }
  }
}

Isometry chainFramePose(const Model& model, const ChainPoses& poses, int frame_id) {
  const Frame& f = model.frames[frame_id];
  return poses.oMb[f.body] * f.placement;
}

void chainFrameJacobian(const Model& model, const ChainPoses& poses, int frame_id, Matrix6x7& J) {
  const Frame& f = model.frames[frame_id];
  const Vector3 p = poses.oMb[f.body] * f.placement.translation();
  J.setZero();
  // a revolute joint k moves the point p at axis_k x (p - origin_k)
  for (int k = 1; k <= f.body; ++k) {
    J.col(k - 1).head<3>() = poses.axis[k].cross(p - poses.oMb[k].translation());
    J.col(k - 1).tail<3>() = poses.axis[k];
  }
}

}  // namespace handover::control::grasp
