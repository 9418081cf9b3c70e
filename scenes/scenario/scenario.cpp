#include "scenes/scenario/scenario.hpp"

namespace handover::scenario {

Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d poseFromPosRpy(const Eigen::Vector3d& pos, const Eigen::Vector3d& rpy) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotationFromRpy(rpy);
  T.translation() = pos;
  return T;
}

const char* toString(Mode m) { return m == Mode::HumanToRobot ? "human_to_robot" : "robot_to_human"; }

const char* toString(StepKind k) {
  switch (k) {
    case StepKind::Reach: return "reach";
    case StepKind::Withdraw: return "withdraw";
    case StepKind::Hold: return "hold";
    case StepKind::Wait: return "wait";
    case StepKind::Release: return "release";
    case StepKind::Grasp: return "grasp";
    case StepKind::Pull: return "pull";
  }
  return "?";
}

const char* toString(WaitUntil w) {
  switch (w) {
    case WaitUntil::FingersOnObject: return "fingers_on_object";
    case WaitUntil::ObjectFree: return "object_free";
    case WaitUntil::ObjectInReach: return "object_in_reach";
  }
  return "?";
}

const char* toString(Shape s) {
  switch (s) {
    case Shape::Cylinder: return "cylinder";
    case Shape::Box: return "box";
    case Shape::Sphere: return "sphere";
  }
  return "?";
}

}  // namespace handover::scenario
