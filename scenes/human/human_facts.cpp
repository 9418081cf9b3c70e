#include "scenes/human/human_facts.hpp"

#include "scenes/scenario/object_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace handover::human {

double distanceToObject(const scenario::ObjectSpec& object, const Eigen::Isometry3d& object_pose,
                        const Eigen::Vector3d& point_world) {
  return std::max(0.0, scenario::signedDistanceToObject(object, object_pose.inverse() * point_world));
}

HumanFacts computeHumanFacts(const sim::ContactReport& contacts, const sim::ObjectState& object_state,
                             const scenario::ObjectSpec& object, const Eigen::Isometry3d& hand_pose) {
  HumanFacts f;
  f.fingers_on_object = contacts.left_finger_on_object && contacts.right_finger_on_object;
  f.object_free = !contacts.left_finger_on_object && !contacts.right_finger_on_object;
  f.object_distance = distanceToObject(object, object_state.pose, hand_pose.translation());
  f.object_speed = object_state.velocity.head<3>().norm();
  f.object_in_reach = f.object_distance <= kInReachDistance && f.object_speed < kInReachSpeed;
  return f;
}

}  // namespace handover::human
