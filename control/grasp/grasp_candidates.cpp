#include "control/grasp/grasp_candidates.hpp"

#include <cmath>

namespace handover::control::grasp {

namespace {

// The half turn about the approach axis equals the half turn about the free
// axis when both are the same line (axis along grasp z, through the grasp point).
bool twinIsATurn(const GraspSpec& spec) {
  const Vector3 a = spec.free_axis.normalized();
  const Vector3 z = spec.placement.linear().col(2);
  const bool parallel = std::abs(a.dot(z)) > 1.0 - 1e-9;
  const bool through_point = a.cross(spec.placement.translation()).norm() < 1e-9;
  return parallel && through_point;
}

}  // namespace

std::vector<GraspCandidate> enumerateGraspCandidates(const std::vector<GraspSpec>& specs,
                                                     const CandidateOptions& options) {
  std::vector<GraspCandidate> out;
  const Isometry half_turn(Eigen::AngleAxisd(M_PI, Vector3::UnitZ()));
  for (int s = 0; s < static_cast<int>(specs.size()); ++s) {
    const GraspSpec& spec = specs[s];
    const int turns = spec.has_free_axis ? std::max(1, static_cast<int>(std::lround(2.0 * M_PI / options.free_axis_step))) : 1;
    const bool twins = options.parallel_gripper_twin && !(spec.has_free_axis && turns % 2 == 0 && twinIsATurn(spec));
    for (int k = 0; k < turns; ++k) {
      GraspCandidate c;
      c.spec = s;
      c.turn = 2.0 * M_PI * k / turns;
      const Isometry turn(Eigen::AngleAxisd(c.turn, spec.has_free_axis ? Vector3(spec.free_axis.normalized()) : Vector3::UnitZ()));
      c.in_object = turn * spec.placement;
      out.push_back(c);
      if (twins) {
        c.twin = true;
        c.in_object = c.in_object * half_turn;
        out.push_back(c);
      }
    }
  }
  return out;
}

}  // namespace handover::control::grasp
