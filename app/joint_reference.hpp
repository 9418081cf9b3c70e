// The joint-reference execution, on the driver side of the robot boundary
// (as the paper's experiment ran mc_rtc on a Panda): the control cycle runs
// on its own integrated joint state (q_ref, qdot_ref) instead of the measured
// one, and a joint impedance makes the arm follow it,
//   tau = tau_cycle + Kp (q_ref - q) + Kd (qdot_ref - qdot),
// so model errors between the controller and the arm do not bias soft
// task-space gains. Used by the paper experiment (--execution reference) and
// `handover hold`; the cycle itself is unchanged (it is just given q_ref).
// Units: rad, rad/s, N m. Real-time safe (fixed-size values only).
#pragma once

#include "interfaces/arm_io.hpp"

namespace handover::app {

class JointReferenceExecution {
 public:
  /// Starts the reference at `q0`, at rest; `kp` N m/rad, `kd` N m s/rad.
  JointReferenceExecution(const io::Vector7& q0, const io::Vector7& kp, const io::Vector7& kd)
      : q_ref_(q0), qd_ref_(io::Vector7::Zero()), kp_(kp), kd_(kd) {}

  /// What the cycle is given: the measured state with the reference joints.
  io::ArmState seen(const io::ArmState& measured) const {
    io::ArmState s = measured;
    s.q = q_ref_;
    s.qd = qd_ref_;
    return s;
  }

  /// The command for the arm: the cycle's plus the impedance on the measured
  /// state. Then the reference moves on by the cycle's joint acceleration
  /// `qdd` (rad/s^2) over `dt` s, semi-implicit Euler like the controller's own integrator.
  io::ArmCommand command(const io::ArmCommand& cycle, const io::ArmState& measured, const io::Vector7& qdd,
                         double dt) {
    io::ArmCommand c = cycle;
    c.tau += kp_.cwiseProduct(q_ref_ - measured.q) + kd_.cwiseProduct(qd_ref_ - measured.qd);
    qd_ref_ += qdd * dt;
    q_ref_ += qd_ref_ * dt;
    return c;
  }

  const io::Vector7& q() const { return q_ref_; }
  const io::Vector7& qd() const { return qd_ref_; }

 private:
  io::Vector7 q_ref_, qd_ref_, kp_, kd_;
};

}  // namespace handover::app
