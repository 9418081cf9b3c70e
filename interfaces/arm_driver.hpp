// The arm as the control cycle sees it: read the state, apply a command.
// sim::Simulation is one driver; a real robot's driver is another (its
// state() reads the robot's last sample, apply() sends the torques and the
// gripper target). Both calls must be real-time safe in a driver meant for a
// 1 ms loop (no allocation, no blocking I/O beyond the robot's own link).
#pragma once

#include "interfaces/arm_io.hpp"

namespace handover::io {

class ArmDriver {
 public:
  virtual ~ArmDriver() = default;
  /// The latest state of the arm (joints, fingers, wrist wrench).
  virtual ArmState state() const = 0;
  /// Sends one cycle's command; it holds until the next apply().
  virtual void apply(const ArmCommand& command) = 0;
};

}  // namespace handover::io
