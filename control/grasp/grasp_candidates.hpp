// The grasps an object admits, enumerated once in the object's frame.
//
// A declared grasp is a grasp frame in the object frame (design notes:
// grasp z = approach axis, fingers close along grasp y). It expands into:
// - with a free axis (the object is symmetric about an axis of its frame,
//   through its origin): the grasp turned about that axis every
//   `free_axis_step`, the turn carrying the grasp point with it;
// - for a parallel gripper: each of those and its half-turn twin (rotated by
//   pi about its own approach axis), which closes the fingers on the same
//   points with the wrist turned by pi.
// Candidates are fixed in the object frame, so their identity (the index)
// stays the same as the object moves: that is what hysteresis holds on to.
// Frames: object frame for the candidates, world for the posed frames. Units: m, rad.
#pragma once

#include <cmath>
#include <vector>

#include "control/types.hpp"

namespace handover::control::grasp {

/// One grasp the object declares (scenario `object.grasp` or an entry of `object.grasps`).
struct GraspSpec {
  Isometry placement = Isometry::Identity();  ///< X_grasp^obj: grasp frame in the object frame
  bool has_free_axis = false;
  Vector3 free_axis = Vector3::UnitZ();       ///< object frame, unit; any turn about it (through the origin) is admissible
  /// Score units added to its candidates' total (grasp_score.hpp): a grasp the
  /// object declares is preferred to one its shape merely allows.
  double preference = 0.0;
};

struct CandidateOptions {
  double free_axis_step = 30.0 * M_PI / 180.0;  ///< rad, spacing of the turns about a free axis (> 0)
  bool parallel_gripper_twin = true;            ///< add each candidate's half-turn twin
  double pre_grasp_standoff = 0.10;             ///< m, pre-grasp distance back along the approach axis
};

/// One admissible grasp, fixed in the object frame.
struct GraspCandidate {
  int spec = 0;                                ///< index of the GraspSpec it came from
  double turn = 0.0;                           ///< rad, turn about the free axis (0 without one)
  bool twin = false;                           ///< the half-turn twin about the approach axis
  Isometry in_object = Isometry::Identity();   ///< grasp frame in the object frame
};

/// Every candidate of `specs` (in spec order; per spec, turns ascending from 0,
/// each followed by its twin). When the free axis runs along the approach axis
/// through the grasp point and the turns include pi, the twins coincide with
/// turns and are left out. Allocates: call at start-up or when the grasps change.
std::vector<GraspCandidate> enumerateGraspCandidates(const std::vector<GraspSpec>& specs,
                                                     const CandidateOptions& options);

/// World grasp frame of a candidate for the object at X_obj (world). RT safe.
inline Isometry graspInWorld(const Isometry& X_obj, const GraspCandidate& c) { return X_obj * c.in_object; }

/// Pre-grasp frame: the grasp frame moved back by `standoff` (m) along its -z. RT safe.
inline Isometry preGraspOf(const Isometry& X_grasp, double standoff) {
  return X_grasp * Eigen::Translation3d(0.0, 0.0, -standoff);
}

}  // namespace handover::control::grasp
