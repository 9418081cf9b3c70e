#include "scenes/scenario/scenario_check.hpp"

#include <sstream>

#include "config/input_error.hpp"
#include "scenes/scenario/object_geometry.hpp"
#include "scenes/scenario/scenario_bounds.hpp"

namespace handover::scenario {

void failAt(const SourceRef& where, const std::string& message) {
  std::ostringstream os;
  os << where.file;
  if (where.line > 0) os << ":" << where.line;
  os << ": ";
  if (!where.key.empty()) os << "key '" << where.key << "': ";
  os << message;
  throw InputError(os.str());
}

namespace {

void checkReach(const Scenario& s, const Eigen::Vector3d& shoulder, const BodyDimensions& body,
                const Eigen::Vector3d& target, const SourceRef& where, const char* what) {
  const double d = (target - shoulder).norm();
  std::ostringstream os;
  os.precision(3);
  if (d > body.reach()) {
    os << what << " (" << target.x() << ", " << target.y() << ", " << target.z() << ") is " << d
       << " m from the " << (s.human.hand == HandSide::Right ? "right" : "left") << " shoulder at ("
       << shoulder.x() << ", " << shoulder.y() << ", " << shoulder.z() << "); a " << body.height
       << " m person reaches " << body.reach() << " m";
    failAt(where, os.str());
  }
  if (d < kMinShoulderToGrip) {
    os << what << " is " << d << " m from the shoulder; the hand cannot be that close to it";
    failAt(where, os.str());
  }
  if (target.z() < kFloorZ + 0.05) failAt(where, std::string(what) + " is below the floor");
}

std::string mm(double m) {
  std::ostringstream os;
  os.precision(3);
  os << m * 1e3 << " mm";
  return os.str();
}

// the object fits the gripper at a grasp frame, which lies on or in it
void checkGraspFits(const ObjectSpec& o, const SourceRef& grasp_where) {
  const double width = objectWidthAcrossFingers(o);
  if (width > kGripperOpening) {
    failAt(grasp_where, "the object is " + mm(width) + " wide across the fingers (the grasp frame's y axis); the gripper opens " +
                            mm(kGripperOpening) + " (turn the grasp so the fingers close across a narrower side)");
  }
  const double d_grasp = signedDistanceToObject(o, o.grasp.translation());
  if (d_grasp > kMaxGraspToSurface) {
    failAt(grasp_where, "the grasp frame is " + mm(d_grasp) + " outside the object's surface; the fingers close within " +
                            mm(kMaxGraspToSurface) + " of it");
  }
}

// every grasp fits, and the person's grip point is at the object
void checkObjectPoses(const Scenario& s) {
  const ObjectSpec& o = s.object;
  SourceRef grasp_where = s.object_where;
  grasp_where.key += ".grasp";
  checkGraspFits(o, grasp_where);
  for (std::size_t i = 0; i < o.grasps.size(); ++i) {  // every declared grasp, the same way
    ObjectSpec other = o;
    other.grasp = o.grasps[i].grasp;
    SourceRef where = s.object_where;
    where.key += ".grasps[" + std::to_string(i) + "]";
    checkGraspFits(other, where);
  }
  if (s.human.holds_object) {
    // the grip point (hand origin) in the object frame
    const Eigen::Vector3d grip = s.human.holds_object->inverse().translation();
    const double d_hold = signedDistanceToObject(o, grip);
    if (d_hold > kMaxHoldToSurface) {
      failAt(s.human.holds_where, "the object's surface is " + mm(d_hold) + " from the hand's grip point; a held object is within " +
                                      mm(kMaxHoldToSurface) + " of it");
    }
  }
}

}  // namespace

void checkScenario(const Scenario& s) {
  const HumanSpec& h = s.human;
  checkObjectPoses(s);
  // who holds the object at the start must fit the direction of the handover
  if (s.mode == Mode::HumanToRobot) {
    if (s.robot.holds_object) failAt(s.robot_holds_where, "human_to_robot: the robot must start empty (holds_object: false)");
    if (!h.holds_object) failAt(s.mode_where, "human_to_robot: the person must start holding the object (human.holds_object)");
  } else {
    if (!s.robot.holds_object) failAt(s.robot_holds_where, "robot_to_human: the robot must start holding the object (robot.holds_object: true)");
    if (h.holds_object) failAt(h.holds_where, "robot_to_human: the person's hand must start empty (remove human.holds_object)");
  }

  const BodyDimensions body = bodyDimensionsFromHeight(h.height);
  const Eigen::Vector3d shoulder = shoulderPosition(body, h.stand_pos, h.stand_yaw, h.hand);
  checkReach(s, shoulder, body, h.start.translation(), h.start_where, "start hand position");

  // walk the script, tracking the hand position and whether it holds the object
  Eigen::Vector3d hand = h.start.translation();
  // a grasp may miss at run time, so after one the hand only "maybe" holds
  enum class Held { Yes, No, Maybe } held = h.holds_object ? Held::Yes : Held::No;
  for (const ScriptStep& st : h.script) {
    switch (st.kind) {
      case StepKind::Reach:
      case StepKind::Withdraw:
        hand = st.pos;
        checkReach(s, shoulder, body, hand, st.target_where, st.kind == StepKind::Reach ? "reach target" : "withdraw target");
        break;
      case StepKind::Pull:
        hand += st.dir * st.distance;
        checkReach(s, shoulder, body, hand, st.target_where, "pull end");
        break;
      case StepKind::Release:
        if (held == Held::No) failAt(st.where, "release: the hand holds nothing at this point of the script");
        held = Held::No;
        break;
      case StepKind::Grasp:
        if (held == Held::Yes) failAt(st.where, "grasp: the hand already holds the object at this point of the script");
        held = Held::Maybe;
        break;
      case StepKind::Hold:
      case StepKind::Wait:
        break;
    }
  }
}

}  // namespace handover::scenario
