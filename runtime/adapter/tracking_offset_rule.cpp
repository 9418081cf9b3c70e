#include "runtime/adapter/tracking_offset_rule.hpp"

namespace handover::runtime {

control::GraspOffset makeTrackingOffset(const control::Isometry& placement, const control::GraspOffset& object_grasp,
                                    bool follows_object, bool planned, const control::Vector7& joint_plan) {
  control::GraspOffset g;
  g.placement = placement;
  if (planned) {
    g.has_joint_plan = true;
    g.joint_plan = joint_plan;
    return g;
  }
  g.has_free_axis = follows_object && object_grasp.has_free_axis;
  g.free_axis = object_grasp.free_axis;
  // a symmetric object is taken from the robot's side (the base is the world origin)
  g.approach_from_base = true;
  g.base = control::Vector3::Zero();
  g.parallel_gripper = follows_object;
  return g;
}

}  // namespace handover::runtime
