#include "control/grasp/grasp_score.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace handover::control::grasp {

double smallestLimitDistance(const Model& model, const Vector7& q) {
  return std::min((q - model.q_min).minCoeff(), (model.q_max - q).minCoeff());
}

double manipulability(const Matrix6x7& J) {
  const Matrix6 JJt = J * J.transpose();
  // det of a symmetric positive semi-definite matrix from its LDL' pivots
  const Eigen::LDLT<Matrix6> ldlt(JJt);
  double det = 1.0;
  for (int i = 0; i < 6; ++i) det *= std::max(0.0, ldlt.vectorD()[i]);
  return std::sqrt(det);
}

ScoreTerms scoreConfiguration(const Model& model, int frame_id, const ChainPoses& poses, const Vector7& q,
                              const Vector7& q_now, const ObstacleCapsule* obstacles, int num_obstacles,
                              const ScoreWeights& w) {
  ScoreTerms t;
  t.joint_margin = std::clamp(smallestLimitDistance(model, q) / w.margin_ref, 0.0, 1.0);
  Matrix6x7 J;
  chainFrameJacobian(model, poses, frame_id, J);
  t.manipulability = std::min(1.0, manipulability(J) / w.manipulability_ref);
  t.motion = (q - q_now).norm() / w.motion_ref;
  if (num_obstacles > 0) {
    const double d = armClearance(model, poses, obstacles, num_obstacles);
    t.clearance = std::clamp(1.0 - d / w.clearance_ref, 0.0, 1.0);
    // squared: millimetres short are the sensing budget at work, centimetres miss the palm
    const double s = keepShortfall(model, poses, obstacles, num_obstacles) / w.shortfall_ref;
    t.shortfall = std::min(1.0, s * s);
  }
  t.total = totalScore(t, w);
  return t;
}

double exitBlock(const Isometry& grasp, const Vector3& pull) {
  const double into_finger = std::abs(grasp.linear().col(1).dot(pull));
  const double into_palm = std::min(1.0, 2.0 * std::max(0.0, -grasp.linear().col(2).dot(pull)));
  return std::min(1.0, std::max(into_finger, into_palm));
}

double totalScore(const ScoreTerms& t, const ScoreWeights& w) {
  return w.joint_margin * t.joint_margin + w.manipulability * t.manipulability - w.motion * t.motion -
         w.clearance * t.clearance - w.shortfall * t.shortfall;
}

}  // namespace handover::control::grasp
