// The registry the controller is assembled from (TSID-style): each entry of
// config/controller.yaml's `tasks:` and `constraints:` lists names a type,
// and the registry maps the type to a factory that builds the task or
// constraint from the entry's parameters. A new task is a class, a factory
// line (addTask) and a YAML entry:
//
//   ControllerRegistry registry = ControllerRegistry::shipped();
//   registry.addTask("wrist_damping", [](const ElementArgs& a) {
//     return BuiltTask{std::make_shared<WristDampingTask>(a.name, a.params.getDouble("damping")),
//                      a.params.getDouble("weight")};
//   });
//   tasks:
//     - {name: wrist_damping, type: wrist_damping, damping: 20.0, weight: 1.0e-3}
//
// Shipped types: tasks observation, trajectory_tracking, posture, pose;
// constraints joint_acceleration_limit, joint_position_limit,
// joint_velocity_limit, joint_torque_limit (parameters: the typed sections
// of ControllerConfig, so scenario `set:` keys keep their spelling) and
// collision (the collision scene the caller hands the controller,
// config/collision.yaml; without one the entry is skipped: model checks and
// unit tests run without a scene).
// Start-up only: building allocates and throws handover::InputError naming
// the file, the entry and the line.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "config/yaml_reader.hpp"
#include "control/collision/collision_config.hpp"
#include "control/controller_config.hpp"
#include "control/formulation/constraint.hpp"
#include "control/formulation/task.hpp"
#include "control/model/model.hpp"

namespace handover::control {

/// What a factory builds from.
struct ElementArgs {
  const Model& model;
  const ControllerConfig& config;    ///< the typed sections (the shipped types' parameters)
  const std::string& name;           ///< the entry's name: the task's or constraint's name()
  const YamlReader& params;          ///< the entry: read your parameters; unread keys are refused
  const CollisionConfig* collision;  ///< the collision scene, or null when the caller has none
};

/// A built task and its weights in the QP (row_weights empty: all 1).
struct BuiltTask {
  std::shared_ptr<Task> task;
  double weight = 1.0;
  Eigen::VectorXd row_weights;
};

using TaskFactory = std::function<BuiltTask(const ElementArgs&)>;
/// May return null: the constraint does not apply here (collision without a scene).
using ConstraintFactory = std::function<std::shared_ptr<Constraint>(const ElementArgs&)>;

class ControllerRegistry {
 public:
  /// An empty registry.
  ControllerRegistry() = default;
  /// The shipped types (above).
  static ControllerRegistry shipped();

  /// Registers a type; throws std::invalid_argument if it is already registered.
  void addTask(const std::string& type, TaskFactory factory);
  void addConstraint(const std::string& type, ConstraintFactory factory);
  bool hasTask(const std::string& type) const { return tasks_.count(type) > 0; }
  bool hasConstraint(const std::string& type) const { return constraints_.count(type) > 0; }

  /// Builds an entry of config.tasks / config.constraints; throws InputError
  /// on an unknown type, a parameter the factory did not read, or a name
  /// that differs from the entry's.
  BuiltTask buildTask(const ElementEntry& entry, const Model& model, const ControllerConfig& config,
                      const CollisionConfig* collision) const;
  std::shared_ptr<Constraint> buildConstraint(const ElementEntry& entry, const Model& model,
                                              const ControllerConfig& config, const CollisionConfig* collision) const;

 private:
  std::map<std::string, TaskFactory> tasks_;
  std::map<std::string, ConstraintFactory> constraints_;
};

}  // namespace handover::control
