// Plain structs between the controller side and an arm: the simulator or a
// real robot driver (Drake / ros2_control style: state in, command out). The
// controller never sees the driver's internals.
// Units SI; joint vectors are the 7 arm joints in chain order.
#pragma once

#include <Eigen/Core>

namespace handover::io {

using Vector7 = Eigen::Matrix<double, 7, 1>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

/// What the arm's own sensors report each 1 ms cycle.
struct ArmState {
  double time = 0.0;                 ///< s since the start of the run
  Vector7 q = Vector7::Zero();       ///< joint positions, rad
  Vector7 qd = Vector7::Zero();      ///< joint velocities, rad/s
  Vector7 tau_measured = Vector7::Zero();  ///< applied joint torques, N m
  double finger_width = 0.0;         ///< total opening between the fingers, m
  /// Wrist force-torque sensor, [force (N); torque (N m)] that the hand exerts
  /// on the flange, expressed in the "ft_sensor" frame. With an empty hand at
  /// rest it reads the hand's own weight (docs/simulation.md: sign convention).
  Vector6 wrench = Vector6::Zero();
};

/// What the controller sends each 1 ms cycle.
struct ArmCommand {
  Vector7 tau = Vector7::Zero();     ///< joint torques, N m (the driver clamps them to the limits)
  double gripper_width = 0.08;       ///< total finger opening target, m (0 = close fully)
  double gripper_force = 70.0;       ///< grasp force limit, N
};

}  // namespace handover::io
