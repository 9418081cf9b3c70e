// Controller settings (config/controller.yaml) and their strict loader.
// Start-up only (allocates, throws); nothing here runs in the control step.
// Units: stiffness 1/s^2, damping 1/s, weights unitless, scales fractions of
// the datasheet limits, period s.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "config/yaml_reader.hpp"
#include "control/constraints/gravity_hold_limit.hpp"
#include "control/constraints/joint_position_limit.hpp"
#include "control/model/joint_limits.hpp"
#include "control/safety/limit_guard.hpp"
#include "control/tasks/pd_gains.hpp"
#include "control/wrench/contact_wrench.hpp"
#include "control/wrench/disturbance_observer.hpp"
#include "control/types.hpp"

namespace handover::control {

/// Gains of one part (translation or orientation) of a Cartesian task, with
/// its per-axis row weights (world axes).
struct AxisGains {
  PdGains gains;
  Vector3 weights = Vector3::Ones();
};

/// One entry of controller.yaml's `tasks:` or `constraints:` list: a task or
/// constraint the controller builds, in list order, through the registry
/// (control/controller_registry.hpp): its name (what the state machine and
/// logs call it), its registered type, whether it starts enabled, and the
/// entry itself, whose other keys are the type's parameters (read by the
/// type's factory; a key it does not read is an error).
struct ElementEntry {
  std::string name;
  std::string type;
  bool enabled = true;
  /// The entry's map (null for a default entry: no parameters). Held by
  /// pointer: assigning one YAML::Node to another rebinds the node it
  /// referred to (yaml-cpp), which a copy of the config must never do.
  std::shared_ptr<const YAML::Node> node;
  std::string file;  ///< where it was read (messages)
  std::string path;  ///< dotted key of the entry, e.g. "tasks[1]"
};

/// The shipped task list: observation, tracking (trajectory_tracking),
/// posture, pose (off at start); and constraint list: the four joint limits
/// then collision. What an absent `tasks:` / `constraints:` key means.
std::vector<ElementEntry> defaultTaskEntries();
std::vector<ElementEntry> defaultConstraintEntries();

struct ControllerConfig {
  double period = 0.001;  ///< control period dt, s
  std::string frame = "tcp";  ///< model frame that grasps

  /// What the QP is assembled from, in order (controller_registry.hpp). The
  /// shipped types read their gains and weights from the typed sections
  /// below (observation, tracking, posture, pose_task, limits), so that
  /// scenario `set:` keys keep their spelling.
  std::vector<ElementEntry> tasks = defaultTaskEntries();
  std::vector<ElementEntry> constraints = defaultConstraintEntries();

  struct Observation {
    PdGains gains = PdGains::critical(1500.0);
    double weight = 1e7;
  } observation;

  struct Tracking {
    double weight = 1e5;
    AxisGains translation{PdGains::critical(1.0)};
    AxisGains orientation{PdGains::critical(2.0)};
    /// Speed limit of the approach (0 = none): the PD's error is clipped
    /// so that it asks at most this speed relative to the target (m/s,
    /// rad/s). Stiff gains then converge fast near the target without
    /// rushing at it from afar (TrajectoryTrackingTask::setSpeedLimits).
    double max_speed = 0.0;
    double max_angular_speed = 0.0;
  } tracking;

  struct Posture {
    PdGains gains = PdGains::critical(10.0);
    double weight = 5.0;
    Vector7 target = (Vector7() << 0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398).finished();
  } posture;

  struct PoseTask {
    double weight = 1e5;
    AxisGains translation{PdGains::critical(2.0)};
    AxisGains orientation{PdGains::critical(2.0)};
  } pose_task;

  struct Limits {
    JointPositionLimitParams position;
    double velocity_scale = 0.8;
    /// Fraction of the datasheet acceleration a joint may brake with to stop
    /// before its position limit: its speed toward the limit is capped so it
    /// can (JointVelocityLimit; 0 = no cap, the position damper alone).
    double velocity_braking = 0.0;
    double acceleration_scale = 1.0;
    double torque_scale = 1.0;
    /// The most of each scaled torque limit gravity may take (GravityHoldLimit;
    /// the start-up validation holds the start posture to the same share).
    GravityHoldParams gravity_hold;
  } limits;

  struct Qp {
    double regularisation = 1e-3;  ///< must stay well above 1e-13 x the largest weight (solver pivot test)
    int max_iterations = 1000;
    /// Relax soft rows (collision) by the least amount when the QP is
    /// infeasible, instead of falling back to the damped stop.
    bool relax_soft_rows = true;
  } qp;

  /// The wrist force-torque sensor's load in the dynamics (contact_wrench.hpp).
  ContactWrenchSettings contact_wrench;
  /// The joint torque the model misses, fed back while carrying (disturbance_observer.hpp).
  DisturbanceSettings disturbance;

  struct Fallback {
    double damping = 20.0;  ///< kd of the damped stop qddot = -kd qdot, 1/s
    /// A run stops when the QP failed in more than this share of the steps
    /// of the last `window` s (read by the application, app/run/fallback_budget.hpp; 1 = never).
    double max_share = 0.2;
    double window = 1.0;    ///< s
  } fallback;

  /// The last line of defence on every command (safety/limit_guard.hpp).
  LimitGuardSettings limit_guard;
};

/// Reads a controller config. Every section and key is optional (defaults
/// above); unknown keys, wrong types and out-of-range values throw
/// InputError naming the file, the dotted key and the line.
ControllerConfig loadControllerConfig(const std::string& path);
/// Same, from an already parsed document (e.g. after scenario overrides).
/// The posture target is checked against the default robot description's
/// joint limits (config/robot.yaml's URDF), or against `joints`.
ControllerConfig parseControllerConfig(const YamlReader& root);
ControllerConfig parseControllerConfig(const YamlReader& root, const JointLimits& joints);
/// The default file: HANDOVER_SOURCE_DIR/config/controller.yaml.
std::string defaultControllerConfigPath();

}  // namespace handover::control
