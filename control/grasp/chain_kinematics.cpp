#include "control/grasp/chain_kinematics.hpp"

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
    poses.oMb[i].linear() = R_joint * Eigen::AngleAxisd(q[i - 1], model.joint_axes[i - 1]).toRotationMatrix();
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
