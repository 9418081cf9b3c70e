// World poses of the person's tracked bodies: what a tracker reports and
// what the simulated person is made of. Frames per design notes 1; m.
#pragma once

#include <Eigen/Geometry>

namespace handover::io {

struct HumanBodyPoses {
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();       ///< grip point frame (design notes 1)
  Eigen::Isometry3d forearm = Eigen::Isometry3d::Identity();    ///< origin at the elbow, z along elbow->wrist
  Eigen::Isometry3d upper_arm = Eigen::Isometry3d::Identity();  ///< origin at the shoulder, z along shoulder->elbow
  Eigen::Isometry3d torso = Eigen::Isometry3d::Identity();      ///< origin on the floor under the body centre, x forward
  double forearm_length = 0.27;    ///< m, elbow to wrist
  double upper_arm_length = 0.33;  ///< m, shoulder to elbow
};

}  // namespace handover::io
