// Helpers for the simulator tests: a joint PD that holds the arm using
// MuJoCo's own bias forces (these tests check the simulator, not our model).
#pragma once

#include "scenes/sim/simulation.hpp"

namespace handover::sim::test {

using Vector7 = Eigen::Matrix<double, 7, 1>;

/// The ready posture (config/controller.yaml posture.target), where load() leaves the arm.
Vector7 readyPosture();

/// One step of tau = Kp (q_ref - q) - Kd qd + qfrc_bias, gripper as given.
void holdStep(Simulation& sim, const Vector7& q_ref, double gripper_width = 0.08, double gripper_force = 70.0);

/// Pose from a position and roll-pitch-yaw (rad).
Eigen::Isometry3d pose(double x, double y, double z, double roll = 0, double pitch = 0, double yaw = 0);

/// The person standing at the scene's default place, hand well away from the arm.
HumanBodyPoses personAway();

/// Largest |efc_pos| over the active equality rows, after mj_forward on a copy
/// of the simulator's data (0 when no equality is active).
double equalityResidual(const Simulation& sim);

}  // namespace handover::sim::test
