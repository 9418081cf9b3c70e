// A task is a least-squares objective || A chi - b ||^2 over the fixed
// variable layout (VariableLayout). The formulation owns its weight; the
// task only fills its rows. Real-time safe: compute() must not allocate.
//
// Besides its rows, a task may take three generic set-points through which
// the state machine addresses any task by its name (Controller::taskIndex,
// fsm::ControllerInterface's task handles): a target, gains and an offset.
// A task without such a notion keeps the default (returns false). Frames:
// world; SI units. Real-time safe: the apply* calls must not allocate.
#pragma once

#include <string>

#include "control/formulation/control_context.hpp"
#include "control/tasks/grasp_frame.hpp"
#include "control/tasks/pd_gains.hpp"

namespace handover::control {

/// A task's reference: the one it was configured with, a pose or joint positions.
struct TaskTarget {
  enum class Kind { kConfigured, kPose, kJoints };
  Kind kind = Kind::kConfigured;
  Isometry pose = Isometry::Identity();  ///< world frame (kPose)
  Vector6 velocity = Vector6::Zero();    ///< kPose: the pose's own motion, [m/s; rad/s] world axes (fed forward)
  Vector7 q = Vector7::Zero();           ///< rad, chain order (kJoints)
  Vector7 qd = Vector7::Zero();          ///< kJoints: the reference's own velocity, rad/s (fed forward)
  Vector7 qdd = Vector7::Zero();         ///< kJoints: ... and acceleration, rad/s^2 (fed forward)
};

/// A task's gains: the configured ones, or the given translation and
/// orientation gains (a joint-space task reads `translation`).
struct TaskGains {
  bool configured = true;
  PdGains translation;  ///< stiffness 1/s^2, damping 1/s
  PdGains orientation;
  double max_speed = 0.0;  ///< m/s, a tracking task's speed limit; 0 = the configured one
};

class Task {
 public:
  virtual ~Task() = default;
  virtual const std::string& name() const = 0;
  /// Number of rows (fixed for the task's lifetime).
  virtual int rows() const = 0;
  /// Fills A (rows() x kNumVars) and b (rows()) so that the task wants A chi = b.
  virtual void compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A,
                       Eigen::Ref<Eigen::VectorXd> b) = 0;

  // -- generic set-points (real-time safe); false: the task has no such notion
  virtual bool applyTarget(const TaskTarget& target) {
    (void)target;
    return false;
  }
  virtual bool applyGains(const TaskGains& gains) {
    (void)gains;
    return false;
  }
  /// The task's frame relative to the observed object (tracking tasks).
  virtual bool applyOffset(const GraspOffset& offset) {
    (void)offset;
    return false;
  }
};

}  // namespace handover::control
