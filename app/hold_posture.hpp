// `handover hold`: the first end-to-end job. A gravity-compensated joint PD
//   tau = Kp (q_ref - q) - Kd qd + g(q)
// holds the arm in a posture in the simulator, with g(q) from our own
// rigid-body model (control::Model from the URDF), never from MuJoCo. It is
// the smallest loop that proves model and simulator agree; later stages
// replace it with the QP controller.
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
  /// posture to hold, rad: the "ready" pose by default
  control::Vector7 q_ref = (control::Vector7() << 0.0, -0.7853981633974483, 0.0, -2.356194490192345, 0.0,
                            1.5707963267948966, 0.7853981633974483).finished();
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

/// Loads the model (URDF) and the simulator, starts the arm at q_ref at rest
/// with the fingers open, and runs the PD for `duration`. Throws
/// handover::InputError (naming the file) for a missing or broken URDF/MJCF
/// or bad options.
HoldSummary holdPosture(const HoldOptions& options);

/// A few lines for the terminal.
void printHoldSummary(std::ostream& out, const HoldSummary& summary);

}  // namespace handover::app
