// What a scenario means for the simulated world and the controller, shared
// by `handover run` and the paper experiment. Start-up only.
#pragma once

#include <string>

#include "control/tasks/grasp_frame.hpp"
#include "scenes/scenario/scenario.hpp"
#include "scenes/sim/sim_options.hpp"

namespace handover::app {

/// HANDOVER_SOURCE_DIR/<relative>
std::string sourcePath(const std::string& relative);

/// Simulator options for the scenario's object and person.
sim::SimOptions simOptionsFor(const scenario::Scenario& sc);

/// Opening (m) the fingers need around the object along the grasp frame's y axis.
double objectWidthAcrossFingers(const scenario::ObjectSpec& object);

/// The grasp frame in the object frame, with the object's symmetry axis.
control::GraspOffset graspOffsetFor(const scenario::ObjectSpec& object);

}  // namespace handover::app
