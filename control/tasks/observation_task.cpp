#include "control/tasks/observation_task.hpp"

#include "control/so3.hpp"

namespace handover::control {

ObservationTask::ObservationTask(std::string name, PdGains translation, PdGains orientation)
    : name_(std::move(name)), translation_(translation), orientation_(orientation) {}

void ObservationTask::setGains(const PdGains& translation, const PdGains& orientation) {
  translation_ = translation;
  orientation_ = orientation;
}

void ObservationTask::compute(const ControlContext& ctx, Eigen::Ref<Eigen::MatrixXd> A,
                              Eigen::Ref<Eigen::VectorXd> b) {
  const ObservedState& obs = ctx.observed;
  error_.head<3>() = obs.pose.translation() - target_.translation();
  error_.tail<3>() = orientationError(obs.pose.linear(), target_.linear());

  // alphadot_obs = -K e - D alpha_obs (the rows touch only the object block)
  A.block<6, 6>(0, VariableLayout::kObs).setIdentity();
  b.head<3>() = -translation_.stiffness * error_.head<3>() - translation_.damping * obs.velocity.head<3>();
  b.tail<3>() = -orientation_.stiffness * error_.tail<3>() - orientation_.damping * obs.velocity.tail<3>();
}

}  // namespace handover::control
