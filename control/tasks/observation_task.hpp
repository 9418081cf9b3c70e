// Observation task (paper II-B): a PD reference model that drives the virtual
// "observed object" frame X_obs toward the measured object pose X_obj:
//
//   alphadot_obs = -K e_obs - D alpha_obs,
//   e_obs = [P_obs - P_obj ; q_obs (-) q_obj]   (orientationError, world axes)
//
// Rows: 6, over the alphadot_obs block of chi only ([linear; angular]).
// Defaults K = 1500, D = 2 sqrt(K) for both parts. The target is whatever was
// set last: the controller holds it when no valid measurement arrives.
// compute() and setTarget() are real-time safe.
#pragma once

#include <string>

#include "control/formulation/task.hpp"
#include "control/tasks/pd_gains.hpp"

namespace handover::control {

class ObservationTask : public Task {
 public:
  explicit ObservationTask(std::string name = "observation",
                           PdGains translation = PdGains::critical(1500.0),
                           PdGains orientation = PdGains::critical(1500.0));

  const std::string& name() const override { return name_; }
  int rows() const override { return 6; }
  void compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::VectorXd> b) override;

  /// Measured object pose X_obj (world).
  void setTarget(const Isometry& target) { target_ = target; }
  const Isometry& target() const { return target_; }
  void setGains(const PdGains& translation, const PdGains& orientation);
  const PdGains& translationGains() const { return translation_; }
  const PdGains& orientationGains() const { return orientation_; }
  /// e_obs of the last compute() (m; rad).
  const Vector6& error() const { return error_; }

 private:
  std::string name_;
  PdGains translation_, orientation_;
  Isometry target_ = Isometry::Identity();
  Vector6 error_ = Vector6::Zero();
};

}  // namespace handover::control
