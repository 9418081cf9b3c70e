// The arm's joint position limits as the robot description's model states
// them (its URDF <limit> tags, config/robot.yaml), for checks that run
// before a controller is built: the scenario's start_q and the controller
// config's posture target. Start-up only (reads files, allocates, throws
// handover::InputError naming the file); not real-time safe.
#pragma once

#include "control/model/robot_description.hpp"
#include "control/types.hpp"

namespace handover::control {

/// Position limits, rad, joints in chain order.
struct JointLimits {
  Vector7 q_min = Vector7::Zero();
  Vector7 q_max = Vector7::Zero();
};

/// The limits of `description`'s model (loads its URDF).
JointLimits jointLimits(const RobotDescription& description);

/// The limits of the default description (config/robot.yaml and its URDF),
/// loaded on the first call and kept for the process (thread-safe).
const JointLimits& defaultJointLimits();

}  // namespace handover::control
