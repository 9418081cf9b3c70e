// The Panda's joint position limits (rad, datasheet; the same numbers as the
// <limit> tags of scenes/panda.urdf, checked by tests/control/controller).
// For validating files before any model is loaded: the scenario's start_q and
// the controller's posture target.
#pragma once

namespace handover::control {

constexpr double kPandaQMin[7] = {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
constexpr double kPandaQMax[7] = {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};

}  // namespace handover::control
