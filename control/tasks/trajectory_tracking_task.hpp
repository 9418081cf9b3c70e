// Trajectory-tracking task (paper II-C): the TCP frame follows the grasp frame
// rigidly attached to the observed object, with the grasp frame's
// acceleration written into the same rows as a linear function of
// alphadot_obs (no one-cycle lag):
//
//   translation (3 rows, world axes):
//     J_p qddot - [I, -[r]x] alphadot_obs = -Kp e_p - Kd edot_p - Jdot_p qdot + w x (w x r)
//     e_p = P_tcp - P_grasp,  r = P_grasp - P_obs,  w = omega_obs
//   orientation, full (3 rows, world axes):
//     J_w qddot - omegadot_obs = -Ko e_o - Do (omega_tcp - omega_obs) - Jdot_w qdot
//     e_o = q_tcp (-) q_grasp (orientationError), or, with a joint plan in the
//     offset, the long way round when the joints' path to the plan turns the
//     TCP that way (planned_turn.hpp)
//   orientation, free axis (3 rows of rank 2): for a symmetric object only the
//   alignment of the gripper's copy b = R_tcp u of the object's axis with the
//   object's axis a = R_obs s matters (u = s in grasp-frame axes). With
//   c = b - a (exactly c'' = -[b]x omegadot_tcp + [a]x omegadot_obs
//   + w_tcp x (w_tcp x b) - w_obs x (w_obs x a)), the rows are that identity
//   set to -Ko c - Do c' and projected on the plane normal to b (rotation
//   about b is free). The grasp point uses the nearest grasp around the axis
//   (frozen within a cycle).
//
// Gains: translation K = 1, D = 2; orientation K = 2, D = 2 sqrt(2) (paper
// defaults). Per-axis weights are row weights held by the Formulation.
// compute() and the setters are real-time safe.
#pragma once

#include <string>

#include "control/formulation/task.hpp"
#include "control/tasks/grasp_frame.hpp"
#include "control/tasks/pd_gains.hpp"
#include "control/tasks/planned_turn.hpp"

namespace handover::control {

class TrajectoryTrackingTask : public Task {
 public:
  /// `frame`: the model frame that must meet the grasp frame (default "tcp").
  /// Throws std::out_of_range naming the frame if the model lacks it.
  TrajectoryTrackingTask(const Model& model, std::string name = "tracking", const std::string& frame = "tcp",
                         PdGains translation = PdGains::critical(1.0),
                         PdGains orientation = PdGains::critical(2.0));

  const std::string& name() const override { return name_; }
  int rows() const override { return 6; }
  void compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::VectorXd> b) override;

  void setGraspOffset(const GraspOffset& offset) { offset_ = offset; }
  /// Generic handles: gains (configured = the constructor's), offset (setGraspOffset).
  bool applyGains(const TaskGains& gains) override;
  bool applyOffset(const GraspOffset& offset) override {
    offset_ = offset;
    return true;
  }
  const GraspOffset& graspOffset() const { return offset_; }
  void setGains(const PdGains& translation, const PdGains& orientation);
  /// Speed limits of the approach, m/s and rad/s (0 = none): the error the
  /// PD acts on is clipped to |e| <= D v_max / K, where a PD asks for
  /// v_max (K e = D v): far from the target the frame closes in at most
  /// v_max, near it the PD converges at its own stiffness. The logged error
  /// stays the true one. Start-up call.
  void setSpeedLimits(double max_speed, double max_angular_speed) {
    max_speed_ = configured_max_speed_ = max_speed;
    max_angular_speed_ = max_angular_speed;
  }
  /// m/s, the speed limit in force (a phase's own or the configured one).
  double maxSpeed() const { return max_speed_; }
  const PdGains& translationGains() const { return translation_; }
  const PdGains& orientationGains() const { return orientation_; }
  int frameId() const { return frame_id_; }

  /// Last compute(): [e_p (m); e_o (rad) or c (axis mode, unitless)].
  const Vector6& error() const { return error_; }
  /// Last compute(): angle between the TCP and the (nearest) grasp orientation, rad.
  double orientationErrorAngle() const { return angle_error_; }

 private:
  std::string name_;
  int frame_id_ = 0;
  PdGains translation_, orientation_;
  PdGains configured_translation_, configured_orientation_;
  double max_speed_ = 0.0, max_angular_speed_ = 0.0;  ///< m/s, rad/s (0 = none)
  double configured_max_speed_ = 0.0;                 ///< m/s: max_speed_ outside a phase's own (applyGains)
  GraspOffset offset_;
  Matrix6x7 J_ = Matrix6x7::Zero();
  Vector6 error_ = Vector6::Zero();
  double angle_error_ = 0.0;
  bool long_way_ = false;  ///< the turn goes the long way round (held where the plan says nothing)
  PlannedTurnLift lift_;   ///< the plan's orientation lifted along the joint path, once per plan
};

}  // namespace handover::control
