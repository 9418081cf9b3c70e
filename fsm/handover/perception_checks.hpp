// Small geometric tests the handover states share. All RT safe.
#pragma once

#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// Speed of `body` toward `center` (m/s, > 0 when approaching).
double speedToward(const Vector3& center, const SensedBody& body);
/// A usable and recent sample.
bool fresh(const SensedBody& body, double max_age);
/// The person withdrew `body`: stale for longer than stale_timeout, outside
/// the workspace, or moving away from it faster than withdraw_speed.
bool withdrawn(const HandoverContext& ctx, const SensedBody& body);
/// Position error (m) and rotation angle error (rad) between two poses.
double positionError(const Isometry& a, const Isometry& b);
double rotationError(const Isometry& a, const Isometry& b);
/// TCP pose, orientation and linear-speed errors against the tracking target
/// all below the given tolerances.
bool alignedWithTarget(const HandoverInput& in, double pos_tol, double rot_tol, double speed_tol);

}  // namespace handover::fsm
