// What a scenario means for the simulated world and the controller, shared
// by `handover run` and the paper experiment. Start-up only.
#pragma once

#include <string>

#include <vector>

#include "control/collision/collision_config.hpp"
#include "control/grasp/palm_fit.hpp"
#include "control/grasp/shape_grasps.hpp"
#include "control/tasks/grasp_frame.hpp"
#include "scenes/scenario/scenario.hpp"
#include "scenes/sim/sim_options.hpp"

namespace handover::app {

/// HANDOVER_SOURCE_DIR/<relative>
std::string sourcePath(const std::string& relative);

/// Simulator options for the scenario's object and person.
sim::SimOptions simOptionsFor(const scenario::Scenario& sc);


/// The grasp frame in the object frame, with the object's symmetry axis.
control::GraspOffset graspOffsetFor(const scenario::ObjectSpec& object);

/// The object as a collision body (the gripper keeps clear of it while approaching).
control::ObjectShapeSettings collisionShapeFor(const scenario::ObjectSpec& object);

/// The grasps the object admits, for the grasp planner (object frame): the
/// declared grasp (with `declared_preference`, score units) and the grasp
/// families its shape allows for a gripper opening to `gripper_opening` (m);
/// a declared grasp deeper than `palm` lets the fingers go moved back to where
/// it does (palm_fit.hpp).
std::vector<control::grasp::GraspSpec> graspSpecsFor(const scenario::ObjectSpec& object, double declared_preference,
                                                     double gripper_opening, const control::grasp::PalmGeometry& palm);

/// The scenario's object as the robot holds it: in a give (robot.holds_object)
/// a declared grasp deeper than `palm` lets the object sit is moved back to
/// where it does (palm_fit.hpp): the object rests against the palm, not in it.
/// A take's object is returned as declared (the grasp planner fits its own).
scenario::ObjectSpec robotHeldObject(const scenario::Scenario& sc, const control::grasp::PalmGeometry& palm);

}  // namespace handover::app
