#include "control/controller_registry.hpp"

#include <stdexcept>

#include "control/constraints/collision_constraint.hpp"
#include "control/constraints/gravity_hold_limit.hpp"
#include "control/constraints/joint_acceleration_limit.hpp"
#include "control/constraints/joint_position_limit.hpp"
#include "control/constraints/joint_torque_limit.hpp"
#include "control/constraints/joint_velocity_limit.hpp"
#include "control/tasks/end_effector_pose_task.hpp"
#include "control/tasks/observation_task.hpp"
#include "control/tasks/posture_task.hpp"
#include "control/tasks/trajectory_tracking_task.hpp"

namespace handover::control {

namespace {

Eigen::VectorXd axisWeights(const AxisGains& translation, const AxisGains& orientation) {
  Eigen::VectorXd w(6);
  w << translation.weights, orientation.weights;
  return w;
}

// the entry as a strict reader (a default entry: an empty map); name, type
// and enabled were read by the config parser
YamlReader entryReader(const ElementEntry& e) {
  const std::string file = e.file.empty() ? std::string("controller config") : e.file;
  YamlReader r(e.node ? *e.node : YAML::Node(YAML::NodeType::Map), file, e.path);
  if (r.isMap()) {
    (void)r.optionalChild("name");
    (void)r.optionalChild("type");
    (void)r.optionalChild("enabled");
  }
  return r;
}

template <class Map>
std::string typeList(const Map& m) {
  std::string out;
  for (const auto& [type, factory] : m) out += (out.empty() ? "" : ", ") + type;
  return out;
}

}  // namespace

ControllerRegistry ControllerRegistry::shipped() {
  ControllerRegistry r;
  r.addTask("observation", [](const ElementArgs& a) {
    const auto& c = a.config.observation;
    return BuiltTask{std::make_shared<ObservationTask>(a.name, c.gains, c.gains), c.weight, {}};
  });
  r.addTask("trajectory_tracking", [](const ElementArgs& a) {
    const auto& c = a.config.tracking;
    auto task = std::make_shared<TrajectoryTrackingTask>(a.model, a.name, a.config.frame, c.translation.gains,
                                                         c.orientation.gains);
    task->setSpeedLimits(c.max_speed, c.max_angular_speed);
    return BuiltTask{task, c.weight, axisWeights(c.translation, c.orientation)};
  });
  r.addTask("posture", [](const ElementArgs& a) {
    const auto& c = a.config.posture;
    return BuiltTask{std::make_shared<PostureTask>(a.name, c.gains, c.target), c.weight, {}};
  });
  r.addTask("pose", [](const ElementArgs& a) {
    const auto& c = a.config.pose_task;
    return BuiltTask{std::make_shared<EndEffectorPoseTask>(a.model, a.name, a.config.frame, c.translation.gains,
                                                           c.orientation.gains),
                     c.weight, axisWeights(c.translation, c.orientation)};
  });
  r.addConstraint("joint_acceleration_limit", [](const ElementArgs& a) -> std::shared_ptr<Constraint> {
    return std::make_shared<JointAccelerationLimit>(a.model, a.config.limits.acceleration_scale, a.name);
  });
  r.addConstraint("joint_position_limit", [](const ElementArgs& a) -> std::shared_ptr<Constraint> {
    return std::make_shared<JointPositionLimit>(a.model, a.config.limits.position, a.name);
  });
  r.addConstraint("joint_velocity_limit", [](const ElementArgs& a) -> std::shared_ptr<Constraint> {
    return std::make_shared<JointVelocityLimit>(a.model, a.config.limits.velocity_scale, a.name,
                                                a.config.limits.velocity_braking, a.config.limits.position.safety);
  });
  r.addConstraint("joint_torque_limit", [](const ElementArgs& a) -> std::shared_ptr<Constraint> {
    return std::make_shared<JointTorqueLimit>(a.model, a.config.limits.torque_scale, a.name);
  });
  r.addConstraint("gravity_hold_limit", [](const ElementArgs& a) -> std::shared_ptr<Constraint> {
    return std::make_shared<GravityHoldLimit>(a.model, a.config.limits.torque_scale, a.config.limits.gravity_hold,
                                              a.name);
  });
  r.addConstraint("collision", [](const ElementArgs& a) -> std::shared_ptr<Constraint> {
    if (a.collision == nullptr) return nullptr;  // no scene here: no collision rows
    return std::make_shared<CollisionConstraint>(a.model, *a.collision, a.name);
  });
  return r;
}

void ControllerRegistry::addTask(const std::string& type, TaskFactory factory) {
  if (!tasks_.emplace(type, std::move(factory)).second)
    throw std::invalid_argument("task type '" + type + "' is registered twice");
}

void ControllerRegistry::addConstraint(const std::string& type, ConstraintFactory factory) {
  if (!constraints_.emplace(type, std::move(factory)).second)
    throw std::invalid_argument("constraint type '" + type + "' is registered twice");
}

BuiltTask ControllerRegistry::buildTask(const ElementEntry& e, const Model& model, const ControllerConfig& config,
                                        const CollisionConfig* collision) const {
  const YamlReader r = entryReader(e);
  const auto f = tasks_.find(e.type);
  if (f == tasks_.end())
    r.fail("task '" + e.name + "': unknown type '" + e.type + "' (registered: " + typeList(tasks_) + ")");
  BuiltTask built = f->second(ElementArgs{model, config, e.name, r, collision});
  r.finish();
  if (!built.task || built.task->name() != e.name)
    r.fail("task '" + e.name + "': the factory of type '" + e.type + "' built no task of that name");
  if (built.row_weights.size() != 0 && built.row_weights.size() != built.task->rows())
    r.fail("task '" + e.name + "': " + std::to_string(built.row_weights.size()) + " row weights for " +
           std::to_string(built.task->rows()) + " rows");
  return built;
}

std::shared_ptr<Constraint> ControllerRegistry::buildConstraint(const ElementEntry& e, const Model& model,
                                                                const ControllerConfig& config,
                                                                const CollisionConfig* collision) const {
  const YamlReader r = entryReader(e);
  const auto f = constraints_.find(e.type);
  if (f == constraints_.end())
    r.fail("constraint '" + e.name + "': unknown type '" + e.type + "' (registered: " + typeList(constraints_) + ")");
  std::shared_ptr<Constraint> built = f->second(ElementArgs{model, config, e.name, r, collision});
  r.finish();
  if (built && built->name() != e.name)
    r.fail("constraint '" + e.name + "': the factory of type '" + e.type + "' built one named '" + built->name() + "'");
  return built;
}

}  // namespace handover::control
