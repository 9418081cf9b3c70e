#include "control/grasp/upright_placement.hpp"

#include <algorithm>
#include <cmath>

namespace handover::control::grasp {

Isometry uprightObjectPose(const Vector3& up_axis, double yaw, const Vector3& position) {
  // the smallest rotation taking the up axis to world z, then the turn about z
  const Matrix3 align = Quaternion::FromTwoVectors(up_axis.normalized(), Vector3::UnitZ()).toRotationMatrix();
  Isometry X = Isometry::Identity();
  X.linear() = Eigen::AngleAxisd(yaw, Vector3::UnitZ()).toRotationMatrix() * align;
  X.translation() = position;
  return X;
}

UprightPlacement findUprightPlacement(const Model& model, const HeldObject& held, const Vector3& position,
                                      const Vector7& q_now, const GraspSelectionConfig& config,
                                      const ObstacleCapsule* obstacles, int num_obstacles) {
  UprightPlacement best;
  const int frame = model.frameId(config.frame);
  const Isometry tcp_in_object = held.object_in_tcp.inverse();
  const Vector3 up = held.up_axis.normalized();
  const UprightOptions& o = config.upright;
  const int turns = std::max(1, static_cast<int>(std::lround(2.0 * M_PI / o.yaw_step)));
  ChainPoses poses;
  for (const Vector3& offset : o.position_offsets) {
    for (int k = 0; k < turns; ++k) {
      const double yaw = 2.0 * M_PI * k / turns;
      const Isometry X_obj = uprightObjectPose(up, yaw, position + offset);
      const Isometry X_tcp = X_obj * tcp_in_object;
      // the current configuration first, then the fixed seeds
      for (int s = -1; s < static_cast<int>(config.seeds.size()); ++s) {
        const IkResult r = solveIk(model, frame, X_tcp, s < 0 ? q_now : config.seeds[s], config.ik);
        ++best.ik_solves;
        if (!r.converged) continue;
        chainPoses(model, r.q, poses);
        if (lowestArmPoint(model, poses) < config.table_height + config.table_clearance) continue;
        const Vector3 up_world = (chainFramePose(model, poses, frame) * held.object_in_tcp).linear() * up;
        const double tilt = std::acos(std::clamp(up_world.z(), -1.0, 1.0));
        if (tilt > o.tilt_tolerance) continue;
        const ScoreTerms t = scoreConfiguration(model, frame, poses, r.q, q_now, obstacles, num_obstacles, config.score);
        if (best.found && t.total <= best.score.total) continue;
        best.found = true;
        best.q = r.q;
        best.tcp = X_tcp;
        best.object = X_obj;
        best.yaw = yaw;
        best.tilt = tilt;
        best.offset = offset;
        best.score = t;
      }
    }
    if (best.found) return best;  // the nominal position (or the nearest offset) wins over a better score farther away
  }
  return best;
}

}  // namespace handover::control::grasp
