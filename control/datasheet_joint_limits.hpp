// The arm's joint position limits (rad, datasheet; the same numbers as the
// <limit> tags of the robot description's URDF, config/robot.yaml, checked
// by tests/control/controller). A stopgap until these checks read the
// description's model (issue 11).
// For validating files before any model is loaded: the scenario's start_q and
// the controller's posture target.
#pragma once

namespace handover::control {

constexpr double kDatasheetQMin[7] = {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
constexpr double kDatasheetQMax[7] = {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};

}  // namespace handover::control
