#include "scenes/human/human_facts.hpp"

#include <algorithm>
#include <cmath>

namespace handover::human {

double distanceToObject(const scenario::ObjectSpec& object, const Eigen::Isometry3d& object_pose,
                        const Eigen::Vector3d& point_world) {
  const Eigen::Vector3d p = object_pose.inverse() * point_world;
  switch (object.shape) {
    case scenario::Shape::Sphere:
      return std::max(0.0, p.norm() - object.size[0]);
    case scenario::Shape::Box: {
      const Eigen::Vector3d half(object.size[0] / 2, object.size[1] / 2, object.size[2] / 2);
      return (p.cwiseAbs() - half).cwiseMax(0.0).norm();
    }
    case scenario::Shape::Cylinder: {
      const double radial = std::max(0.0, std::hypot(p.x(), p.y()) - object.size[0]);
      const double axial = std::max(0.0, std::abs(p.z()) - object.size[1] / 2);
      return std::hypot(radial, axial);
    }
  }
  return 0.0;
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
