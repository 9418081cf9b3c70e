// Example task (docs/architecture.md): damp the wrist joint's velocity,
// qddot_7 = -d qdot_7, as one least-squares row over the QP's variables,
// and its registry line: the type "wrist_damping" built from a YAML entry.
#pragma once

#include <memory>
#include <string>

#include "control/controller_registry.hpp"
#include "control/formulation/task.hpp"

namespace handover::examples {

class WristDampingTask : public control::Task {
 public:
  WristDampingTask(std::string name, double damping) : name_(std::move(name)), damping_(damping) {}
  const std::string& name() const override { return name_; }
  int rows() const override { return 1; }
  void compute(const control::ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A,
               Eigen::Ref<Eigen::VectorXd> b) override {
    A.setZero();
    A(0, control::VariableLayout::kQdd + 6) = 1.0;  // qddot of joint 7
    b(0) = -damping_ * ctx.data->v[6];
    ++calls;
  }
  long calls = 0;  ///< cycles in which the QP asked for the rows

 private:
  std::string name_;
  double damping_;  ///< 1/s
};

/// The registry line: an entry {type: wrist_damping, damping: 1/s, weight: w}.
inline void registerWristDamping(control::ControllerRegistry& registry) {
  registry.addTask("wrist_damping", [](const control::ElementArgs& a) {
    const double damping = a.params.child("damping").checkRange(a.params.getDouble("damping"), 0.0, 1000.0);
    control::BuiltTask built;
    built.task = std::make_shared<WristDampingTask>(a.name, damping);
    built.weight = a.params.getDouble("weight", 1e-3);
    return built;
  });
}

}  // namespace handover::examples
