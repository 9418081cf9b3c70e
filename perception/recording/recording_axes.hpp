// The fixed rotations between a recording's axes and ours (docs/recordings.md):
// its up axis onto our z, a recorded bone frame onto our body frames, and the
// left/right mirror. Pure functions, real-time safe.
#pragma once

#include <Eigen/Geometry>

#include "perception/recording/recording_mapping.hpp"

namespace handover::perception::recording {

/// Rotation taking the recording's world to a z-up one: up = +y is a
/// quarter turn about x (the recording's (x, y, z) become (x, -z, y)),
/// +x a quarter turn about y ((x, y, z) become (-z, y, x)), +z none;
/// a negative up axis adds a half turn.
Eigen::Matrix3d upRotation(const SignedAxis& up);

/// Our bone or object frame in the recorded body frame (columns: our x, y,
/// z): z along `long_axis`, x the next recorded axis in cyclic order
/// (x after z), so R_ours = R_recorded * boneAxes(long_axis).
Eigen::Matrix3d boneAxes(const SignedAxis& long_axis);

/// Our hand frame in the recorded hand frame: x from the fingers toward the
/// wrist (-long_axis), z out of the back of the hand (`back_axis`), y = z x x.
Eigen::Matrix3d handAxes(const SignedAxis& long_axis, const SignedAxis& back_axis);

/// Swaps left and right in our world: reflects y (p -> S p, R -> S R S with
/// S = diag(1, -1, 1)), so a right arm's motion becomes a left arm's.
Eigen::Isometry3d mirrored(const Eigen::Isometry3d& pose);

}  // namespace handover::perception::recording
