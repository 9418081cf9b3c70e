#include "scenes/scenario/scenario_category.hpp"

#include <algorithm>
#include <cmath>

namespace handover::scenario {

namespace {
constexpr double kPi = 3.14159265358979323846;
double deg(double rad) { return rad * 180.0 / kPi; }
}  // namespace

Eigen::Isometry3d presentationHandPose(const HumanSpec& human) {
  Eigen::Isometry3d pose = human.start;
  for (const ScriptStep& st : human.script) {
    if (st.kind == StepKind::Wait || st.kind == StepKind::Release || st.kind == StepKind::Grasp) break;
    if (st.kind == StepKind::Withdraw) continue;  // leaving is not presenting
    if (st.kind == StepKind::Reach) {
      pose.translation() = st.pos;
      if (st.rpy) pose.linear() = rotationFromRpy(*st.rpy);
    }
  }
  return pose;
}

std::string graspFamily(const ObjectSpec& object, const Eigen::Vector3d& up_in_object) {
  const Eigen::Vector3d a = object.grasp.linear().col(2).normalized();
  const Eigen::Vector3d up = up_in_object.normalized();
  if (object.free_axis >= 0) {
    const Eigen::Vector3d f = Eigen::Vector3d::Unit(object.free_axis);
    const bool axis_lies = std::abs(f.dot(up)) < std::sin(30.0 * kPi / 180.0);
    const bool across_axis = std::abs(a.dot(f)) < std::sin(15.0 * kPi / 180.0);
    if (axis_lies && across_axis) return "around_axis";
  }
  const double theta = deg(std::acos(std::clamp(a.dot(-up), -1.0, 1.0)));
  if (theta < 22.5) return "top";
  if (theta < 67.5) return "angled";
  if (theta < 112.5) return "side";
  return "below";
}

std::string standPlacement(const Eigen::Vector2d& stand_xy) {
  if (stand_xy.x() < 0.80) return "side";
  return std::abs(stand_xy.y()) <= 0.15 ? "front" : "offset";
}

Category categoryOf(const Scenario& s) {
  Category c;
  const bool take = s.mode == Mode::HumanToRobot;
  c.direction = take ? "take" : "give";
  c.shape = toString(s.object.shape);
  c.behaviour = s.behaviour.empty() ? "file" : s.behaviour;
  c.placement = standPlacement(s.human.stand_pos);
  c.hand = s.human.hand == HandSide::Right ? "right" : "left";
  const Eigen::Isometry3d hand = presentationHandPose(s.human);
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  if (take && s.human.holds_object) {
    // the object's own axis nearest to the world's vertical as presented: a
    // tilted bottle is still grasped "from the top", a bottle lying is not
    const Eigen::Matrix3d object_in_world = hand.linear() * s.human.holds_object->linear();
    const Eigen::Vector3d v = object_in_world.transpose() * Eigen::Vector3d::UnitZ();
    Eigen::Index i = 0;
    v.cwiseAbs().maxCoeff(&i);
    up = Eigen::Vector3d::Unit(i) * (v[i] < 0.0 ? -1.0 : 1.0);
  }
  c.grasp = graspFamily(s.object, up);
  const double z = hand.translation().z();
  c.height = z < 0.20 ? "low" : z < 0.40 ? "mid" : "high";
  return c;
}

std::string categoryLabel(const Category& c) {
  return c.direction + "/" + c.grasp + "/" + c.shape + "/" + c.behaviour;
}

}  // namespace handover::scenario
