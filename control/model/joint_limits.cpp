#include "control/model/joint_limits.hpp"

#include "control/model/model.hpp"

namespace handover::control {

JointLimits jointLimits(const RobotDescription& description) {
  const Model model = loadModel(description, Model{}.finger_opening);
  JointLimits limits;
  limits.q_min = model.q_min;
  limits.q_max = model.q_max;
  return limits;
}

const JointLimits& defaultJointLimits() {
  // a throwing initialiser leaves the static unset: the next call tries again
  static const JointLimits limits = jointLimits(defaultRobotDescription());
  return limits;
}

}  // namespace handover::control
