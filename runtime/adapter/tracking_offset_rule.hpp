// The rule that turns a tracking placement into the offset the controller's
// tracking task uses: one function, shared by the state machine's adapter
// (grasp, pre-grasp, presentation frames) and the paper experiment (the
// pre-grasp frame), so the two cannot drift apart. Real-time safe.
// Frames: `placement` is the target frame in the observed frame; the robot's
// base is the world origin.
#pragma once

#include "control/tasks/grasp_frame.hpp"

namespace handover::runtime {

/// `object_grasp` carries the object's symmetry (has_free_axis, free_axis);
/// `follows_object`: the observed frame is the object (true) or the
/// person's hand (false). An offset in the object's frame keeps the object's
/// symmetry, is taken from the robot's side, and lets an empty parallel
/// gripper take the object with either finger on either side; one in the
/// hand's frame does none of these. `planned`: the placement is a choice the
/// grasp planner already made with the robot's kinematics (turn about the
/// free axis, twin): it is tracked exactly, none of these rules applies;
/// `joint_plan` is then the configuration planned for it, which decides the
/// way of a large turn (GraspOffset::joint_plan).
control::GraspOffset makeTrackingOffset(const control::Isometry& placement, const control::GraspOffset& object_grasp,
                                    bool follows_object, bool planned = false,
                                    const control::Vector7& joint_plan = control::Vector7::Zero());

}  // namespace handover::runtime
