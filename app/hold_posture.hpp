// `handover hold`: the smallest closed loop, and the proof that our model and
// the simulator agree. It runs the handover's own control cycle
// (runtime::HandoverCycle::step) with a one-state table, config/fsm_hold.yaml
// (Hold: the posture task toward its configured target, the ready posture of
// config/controller.yaml; tracking and pose task off), in the joint-reference
// execution (app/joint_reference.hpp): the cycle is given the reference
// posture, so its command is our model's gravity there (M qddot + h with
// qddot = 0), and the driver side adds the joint PD
//   tau = tau_cycle + Kp (q_ref - q) - Kd qd.
// Gravity comes from our rigid-body model (control::Model from the URDF),
// never from MuJoCo; the TCP drift is measured with our forward kinematics.
#pragma once

#include <ostream>
#include <string>

#include "control/types.hpp"
#include "scenes/sim/sim_options.hpp"

namespace handover::app {

struct HoldOptions {
  double duration = 5.0;  ///< simulated s
  std::string urdf;       ///< robot URDF; empty = the robot description's (config/robot.yaml)
  sim::SimOptions sim;    ///< scene file and world options
  /// N m/rad and N m s/rad. The PD runs explicitly once per 1 ms step and the
  /// wrist joints are light, so Kd * dt stays well below their inertia.
  control::Vector7 kp = (control::Vector7() << 600, 600, 600, 600, 250, 150, 50).finished();
  control::Vector7 kd = (control::Vector7() << 50, 50, 50, 50, 15, 8, 4).finished();
};

struct HoldSummary {
  double simulated_time = 0.0;   ///< s
  double wall_time = 0.0;        ///< s spent in the loop
  double realtime_factor = 0.0;  ///< simulated s per wall s (the loop is not paced)
  double max_tcp_drift = 0.0;    ///< m, largest distance of the TCP (our FK) from its start
  double max_joint_error = 0.0;  ///< rad, largest |q_ref - q| over joints and time
  long steps = 0;
};

/// Loads the cycle (model from the URDF, config/*.yaml, config/fsm_hold.yaml)
/// and the simulator, starts the arm at the held posture at rest with the
/// fingers open, and runs for `duration`. Throws handover::InputError
/// (naming the file) for a missing or broken URDF/MJCF or bad options.
HoldSummary holdPosture(const HoldOptions& options);

/// A few lines for the terminal.
void printHoldSummary(std::ostream& out, const HoldSummary& summary);

}  // namespace handover::app
