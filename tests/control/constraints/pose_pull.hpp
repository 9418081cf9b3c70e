// A controller started at its posture target with the tracking task off and
// the pose task pulling the TCP elsewhere: the demand the limit tests put on
// the QP's constraint rows.
#pragma once

#include <functional>

#include "control/controller.hpp"

namespace handover::test {

/// Resets `ctl` at `cfg`'s posture target, switches tracking off and the pose
/// task on, toward `move(TCP pose at the start)`; returns the start's inputs.
inline control::ControlInputs startPosePull(control::Controller& ctl, const control::ControllerConfig& cfg,
                                            const std::function<control::Isometry(control::Isometry)>& move) {
  control::ControlInputs in;
  in.q = cfg.posture.target;
  ctl.reset(in);
  ctl.setTaskEnabled("tracking", false);
  ctl.setTaskEnabled("pose", true);
  ctl.setPoseTarget(move(ctl.tcpPose()));
  return in;
}

}  // namespace handover::test
