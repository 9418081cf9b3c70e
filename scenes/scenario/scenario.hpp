// A scenario: the person, the object, the sensor and what should happen
// (design notes 2). Built by parseScenario() (scenario_parser.hpp), checked
// by checkScenario() (scenario_check.hpp). Format: docs/scenarios.md.
// World frame, SI units; rotations given in files as roll-pitch-yaw (rad).
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "perception/sensor_settings.hpp"
#include "scenes/scenario/body_dimensions.hpp"

namespace handover::scenario {

using Vector7 = Eigen::Matrix<double, 7, 1>;

/// Where a value came from, for messages ("file:line: key 'a.b': ...").
struct SourceRef {
  std::string file;
  std::string key;  ///< dotted key
  int line = 0;     ///< 1-based, 0 if unknown
};

enum class Mode { HumanToRobot, RobotToHuman };
enum class Shape { Cylinder, Box, Sphere };

/// Rotation from roll-pitch-yaw (rad): R = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy);
/// Pose from a position (m) and roll-pitch-yaw (rad).
Eigen::Isometry3d poseFromPosRpy(const Eigen::Vector3d& pos, const Eigen::Vector3d& rpy);

struct ObjectSpec {
  Shape shape = Shape::Cylinder;
  /// cylinder [radius, height]; box [x, y, z] full edges; sphere [radius]; m
  std::vector<double> size;
  double mass = 0.3;                                       ///< kg
  Eigen::Isometry3d grasp = Eigen::Isometry3d::Identity();  ///< grasp frame in the object frame
  int free_axis = -1;  ///< 0/1/2 = x/y/z axis of symmetry of the object frame, -1 = none
  /// `grasps:` further acceptable grasps (each with its own symmetry axis);
  /// `grasp` stays the first one (categories, grasp error).
  struct ExtraGrasp {
    Eigen::Isometry3d grasp = Eigen::Isometry3d::Identity();  ///< grasp frame in the object frame
    int free_axis = -1;
  };
  std::vector<ExtraGrasp> grasps;
};

struct RobotSpec {
  std::optional<Vector7> start_q;  ///< rad; unset = the controller's default
  bool holds_object = false;       ///< the object starts in the gripper
};

enum class StepKind { Reach, Withdraw, Hold, Wait, Release, Grasp, Pull };
enum class WaitUntil { FingersOnObject, ObjectFree, ObjectInReach };

/// One step of the person's script. Only the fields of its kind are used.
struct ScriptStep {
  StepKind kind = StepKind::Hold;
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();  ///< reach/withdraw: hand target, world, m
  std::optional<Eigen::Vector3d> rpy;             ///< reach/withdraw: target rpy (rad); unset = keep
  double duration = 0.0;                          ///< reach/withdraw/hold/pull: s
  WaitUntil until = WaitUntil::FingersOnObject;   ///< wait: the physical fact waited for
  std::optional<double> timeout;                  ///< wait: s from the wait's start; unset = never
  double delay = 0.0;                             ///< wait: s the fact must hold continuously
  Eigen::Vector3d dir = Eigen::Vector3d::UnitX(); ///< pull: unit direction, world
  double distance = 0.0;                          ///< pull: m
  SourceRef where;                                ///< the step in the file
  SourceRef target_where;                         ///< reach/withdraw: the pos key; pull: distance
};

struct HumanSpec {
  Eigen::Vector2d stand_pos{1.0, 0.0};  ///< floor point under the body centre, world x, y, m
  double stand_yaw = 3.14159265358979;  ///< facing direction, rad about z
  double height = 1.75;                 ///< stature, m
  HandSide hand = HandSide::Right;
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();  ///< hand pose at t = 0, world
  std::optional<Eigen::Isometry3d> holds_object;  ///< object pose in the hand frame; unset = empty hand
  std::vector<ScriptStep> script;
  SourceRef start_where, holds_where;
};

struct Expectations {
  std::optional<std::string> outcome;   ///< success | aborted | hand_contact | object_drop | timeout | no_perception | unsafe | error
  std::optional<int> aborts, retries, handovers;
  std::optional<double> max_total_time;      ///< s, summary total_time <= this
  std::optional<double> min_human_distance;  ///< m, summary min_human_distance >= this
  std::optional<double> max_time_to_grasp;   ///< s, summary time_to_grasp <= this
  std::optional<int> max_human_contacts;     ///< summary human_contacts <= this
  std::optional<bool> object_dropped;        ///< summary object_dropped equals this
};

struct Scenario {
  std::string file;  ///< the scenario file as given
  std::string name;
  Mode mode = Mode::HumanToRobot;
  double duration = 10.0;  ///< s of simulated time at most
  int seed = 0;
  std::string behaviour;    ///< benchmark category's behaviour variant (a word, "" = not given); see scenario_category.hpp
  std::string config_path;  ///< resolved controller config ("" if none given and no default exists)
  YAML::Node config;        ///< the controller config with `set:` applied (null if no config)
  YAML::Node overrides;     ///< the `set:` map as written (null if none)
  ObjectSpec object;
  RobotSpec robot;
  HumanSpec human;
  perception::SensorSettings sensor;
  Expectations expect;
  SourceRef mode_where, robot_holds_where;
  SourceRef config_where;    ///< the `config:` key, else the document
  SourceRef start_q_where;   ///< robot.start_q (empty if not given)
  SourceRef object_where;    ///< the `object:` map
  SourceRef sensor_where;    ///< the `sensor:` map, else the document
  std::vector<std::pair<std::string, SourceRef>> override_where;  ///< each `set:` key, in file order
};

const char* toString(Mode m);
const char* toString(StepKind k);
const char* toString(WaitUntil w);
const char* toString(Shape s);

}  // namespace handover::scenario
