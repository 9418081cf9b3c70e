// Example robot driver (docs/architecture.md): an arm that integrates its
// own rigid-body dynamics, qddot = M(q)^-1 (tau - h(q, qdot)), with our model
// and semi-implicit Euler at 1 ms. A real arm's driver has the same two
// methods: state() returns the last sample, apply() sends the command.
#pragma once

#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "interfaces/arm_driver.hpp"

namespace handover::examples {

class IntegratingArmDriver : public io::ArmDriver {
 public:
  IntegratingArmDriver(const control::Model& model, const io::Vector7& q0) : model_(model), data_(model) {
    state_.q = q0;
    state_.finger_width = 0.08;
  }
  io::ArmState state() const override { return state_; }
  void apply(const io::ArmCommand& command) override {
    control::computeAll(model_, data_, state_.q, state_.qd);
    const io::Vector7 qdd = data_.M.ldlt().solve(command.tau - data_.h);
    state_.qd += kDt * qdd;
    state_.q += kDt * state_.qd;
    state_.tau_measured = command.tau;
    state_.finger_width = command.gripper_width;
    state_.time += kDt;
  }
  static constexpr double kDt = 0.001;  ///< s

 private:
  const control::Model& model_;
  control::Data data_;
  io::ArmState state_;
};

}  // namespace handover::examples
