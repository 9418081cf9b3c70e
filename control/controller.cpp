#include "control/controller.hpp"

#include <algorithm>
#include <cmath>

#include "config/input_error.hpp"
#include "control/qp/goldfarb_idnani.hpp"

namespace handover::control {

namespace {

FormulationCapacity controllerCapacity() {
  FormulationCapacity c;
  c.max_tasks = 16;
  c.max_constraints = 16;
  c.max_constraint_rows = 256;  // room for collision pairs added by the application
  return c;
}

}  // namespace

Controller::Controller(Model model, const ControllerConfig& config, std::unique_ptr<QpSolver> solver)
    : Controller(std::move(model), config, ControllerRegistry::shipped(), nullptr, std::move(solver)) {}

Controller::Controller(Model model, const ControllerConfig& config, const ControllerRegistry& registry,
                       const CollisionConfig* collision, std::unique_ptr<QpSolver> solver)
    : model_(std::move(model)),
      data_(model_),
      config_(config),
      formulation_(controllerCapacity()),
      solver_(std::move(solver)),
      guard_(model_, config.limit_guard, config.period),
      disturbance_(config.disturbance, model_.tau_max, config.period),
      x_(Eigen::VectorXd::Zero(kNumVars)),
      obs_A_(Eigen::MatrixXd::Zero(6, kNumVars)),
      obs_b_(Eigen::VectorXd::Zero(6)) {
  if (!solver_) solver_ = std::make_unique<GoldfarbIdnaniSolver>();
  QpSolverOptions options = solver_->options();
  options.max_iterations = config_.qp.max_iterations;
  solver_->setOptions(options);

  tcp_id_ = model_.frameId(config_.frame);
  ft_id_ = model_.frameId("ft_sensor");
  build(registry, collision);
  formulation_.setRegularisation(config_.qp.regularisation);

  formulation_.reserveProblem(problem_);
  // room for the relaxation's phase 1 (one more variable, soft rows split)
  solver_->reserve(SoftRowRelaxation::solverVars(kNumVars), problem_.capacityEq(),
                   SoftRowRelaxation::solverRowsIn(problem_.capacityIn()));
  relaxation_.reserve(kNumVars, problem_.capacityEq(), problem_.capacityIn());

  ControlInputs start;
  start.q = config_.posture.target;
  reset(start);
}

void Controller::build(const ControllerRegistry& registry, const CollisionConfig* collision) {
  // tasks and constraints in list order; the order of the constraints
  // matters: later bounds give way to earlier ones (bound_tightening.hpp)
  for (const ElementEntry& e : config_.tasks) {
    BuiltTask b = registry.buildTask(e, model_, config_, collision);
    if (b.row_weights.size() == 0) formulation_.addTask(b.task, b.weight);
    else formulation_.addTask(b.task, b.weight, b.row_weights);
    if (!e.enabled) formulation_.setTaskEnabled(e.name, false);
    tasks_.push_back(b.task);
    if (!observation_) observation_ = std::dynamic_pointer_cast<ObservationTask>(b.task);
    if (!tracking_) tracking_ = std::dynamic_pointer_cast<TrajectoryTrackingTask>(b.task);
    if (!posture_) posture_ = std::dynamic_pointer_cast<PostureTask>(b.task);
    if (!pose_) pose_ = std::dynamic_pointer_cast<EndEffectorPoseTask>(b.task);
  }
  for (const ElementEntry& e : config_.constraints) {
    std::shared_ptr<Constraint> c = registry.buildConstraint(e, model_, config_, collision);
    if (!c) continue;  // not here (collision without a scene)
    formulation_.addConstraint(c);
    if (!e.enabled) formulation_.setConstraintEnabled(e.name, false);
    constraints_.push_back(c);
    if (!position_limit_) position_limit_ = std::dynamic_pointer_cast<JointPositionLimit>(c);
    if (!velocity_limit_) velocity_limit_ = std::dynamic_pointer_cast<JointVelocityLimit>(c);
  }
  const std::string file = config_.tasks.empty() || config_.tasks.front().file.empty()
                               ? std::string("controller config")
                               : config_.tasks.front().file;
  if (!observation_ || !tracking_)
    throw InputError(file + ": key 'tasks': the controller needs a task of type observation and one of type "
                            "trajectory_tracking (the observed object and the grasp frame)");
}

int Controller::taskIndex(const std::string& name) const {
  for (std::size_t i = 0; i < tasks_.size(); ++i)
    if (tasks_[i]->name() == name) return static_cast<int>(i);
  return -1;
}

bool Controller::setTaskEnabled(int index, bool enabled) {
  if (index < 0 || index >= numTasks()) return false;
  formulation_.setTaskEnabled(tasks_[index]->name(), enabled);
  return true;
}

bool Controller::taskEnabled(int index) const {
  return index >= 0 && index < numTasks() && formulation_.taskEnabled(tasks_[index]->name());
}

bool Controller::setTaskTarget(int index, const TaskTarget& target) {
  return index >= 0 && index < numTasks() && tasks_[index]->applyTarget(target);
}

bool Controller::setTaskGains(int index, const TaskGains& gains) {
  return index >= 0 && index < numTasks() && tasks_[index]->applyGains(gains);
}

bool Controller::setTaskOffset(int index, const GraspOffset& offset) {
  if (index < 0 || index >= numTasks()) return false;
  GraspOffset o = offset;
  const double n = o.free_axis.norm();
  if (!(n > 1e-9) || !o.free_axis.allFinite()) {
    o.has_free_axis = false;
    o.free_axis = Vector3::UnitZ();
  } else {
    o.free_axis /= n;
  }
  if (!std::isfinite(o.approach_speed) || !std::isfinite(o.approach_acceleration)) {
    o.approach_speed = o.approach_acceleration = 0.0;  // a feed-forward is never worth a NaN
  }
  return tasks_[index]->applyOffset(o);
}

void Controller::reset(const ControlInputs& in) {
  time_ = in.time;
  computeAll(model_, data_, in.q, in.qd);
  const Isometry X_tcp = framePlacement(model_, data_, tcp_id_);
  const Isometry X_obs = X_tcp * tracking_->graspOffset().placement.inverse();
  integrator_.reset(X_obs);
  observation_->setTarget(X_obs);
  has_observation_ = false;
  if (pose_) pose_->setTarget(X_tcp);
  if (position_limit_) position_limit_->reset();
  guard_.reset();
  solver_->resetWarmStart();
  qdd_.setZero();
  tau_ = data_.h;
  external_wrench_.setZero();
  tau_external_.setZero();
  disturbance_.reset();
  frameJacobian(model_, data_, ft_id_, J_ft_);
  status_ = QpStatus::kOptimal;
  iterations_ = 0;
  fell_back_ = false;
  relaxed_ = false;
  unslowed_ = false;
  slack_ = 0.0;
  relaxed_count_ = 0;
  unslowed_count_ = 0;
  fallback_count_ = 0;
  fallback_streak_ = 0;
}

ControlContext Controller::context(double time) const {
  ControlContext ctx;
  ctx.model = &model_;
  ctx.data = &data_;
  ctx.time = time;
  ctx.dt = config_.period;
  ctx.observed = integrator_.state();
  ctx.tau_external = tau_external_;
  return ctx;
}

const Vector7& Controller::step(const ControlInputs& in) {
  fell_back_ = false;
  relaxed_ = false;
  slack_ = 0.0;
  if (!(in.q.allFinite() && in.qd.allFinite() && std::isfinite(in.time))) {
    // keep the last valid kinematics: the damped stop uses the last known state
    status_ = QpStatus::kInvalidProblem;
    iterations_ = 0;
    fallback("non-finite joint state");
    return tau_;
  }
  time_ = in.time;

  // compute once, then tasks and constraints only read
  computeAll(model_, data_, in.q, in.qd);
  frameJacobian(model_, data_, ft_id_, J_ft_);
  disturbance_.update(data_, in.qd, tau_, disturbance_learn_);  // tau_: what the last period applied
  tau_external_.noalias() = (1.0 - disturbance_gain_) * J_ft_.transpose() * external_wrench_;
  if (disturbance_gain_ > 0.0) tau_external_ += disturbance_gain_ * disturbance_.torque();
  const ControlContext ctx = context(in.time);
  formulation_.build(ctx, problem_);

  status_ = solver_->solve(problem_, x_);
  iterations_ = solver_->result().iterations;
  if (status_ == QpStatus::kInfeasible && velocity_limit_ && velocity_limit_->speedScale() < 1.0) {
    // the slow-down yields to the other rows: an arm slowed near a person who
    // moves in faster than it may move could not give way (a receiver's hand
    // reaching at 1 m/s struck the held gripper while the joints crept at
    // 15 % of their limit); the slow-down is for the arm's own motion
    const double slowed = velocity_limit_->speedScale();
    velocity_limit_->setSpeedScale(1.0);
    formulation_.build(ctx, problem_);
    status_ = solver_->solve(problem_, x_);
    iterations_ += solver_->result().iterations;
    velocity_limit_->setSpeedScale(slowed);
    if (status_ == QpStatus::kOptimal) {
      unslowed_ = true;
      ++unslowed_count_;
    }
  }
  if (status_ == QpStatus::kInfeasible && config_.qp.relax_soft_rows && problem_.hasSoftRows()) {
    const QpStatus relaxed = relaxation_.solve(problem_, *solver_, x_);
    iterations_ += relaxation_.iterations();
    if (relaxed == QpStatus::kOptimal && x_.allFinite()) {
      status_ = relaxed;
      relaxed_ = true;
      slack_ = relaxation_.slack();
      ++relaxed_count_;
    }
  }
  if (status_ != QpStatus::kOptimal || !x_.allFinite()) {
    fallback(solver_->result().message);
    return tau_;
  }
  fallback_streak_ = 0;
  qdd_ = x_.head<kArmDofs>();
  integrator_.integrate(x_.segment<kObjDofs>(VariableLayout::kObs), config_.period);
  guardCommand();  // tau = M qddot + h - tau_external, within the limits
  return tau_;
}

void Controller::guardCommand() {
  // the last period's disturbance beyond what the dynamics already hold: the
  // guard predicts the arm's next velocity with it (limit_guard.hpp)
  const Vector7 unmodelled = disturbance_.latest() - tau_external_;
  guard_.apply(data_, tau_external_, qdd_, tau_, unmodelled);
}

void Controller::fallback(const char* why) {
  fell_back_ = true;
  ++fallback_count_;
  ++fallback_streak_;

  // damped stop within the acceleration limits
  const Vector7 a_lim = config_.limits.acceleration_scale * model_.a_max;
  qdd_ = (-config_.fallback.damping * data_.v).cwiseMax(-a_lim).cwiseMin(a_lim);
  // the torque from the model, within the limits, braking before the position limits
  guardCommand();

  // the observed object keeps following its reference model on its own
  const ControlContext ctx = context(time_);
  obs_A_.setZero();
  observation_->compute(ctx, obs_A_, obs_b_);
  integrator_.integrate(Vector6(obs_b_), config_.period);

  // counted, not printed: the step stays free of I/O; the application logs
  fallback_reason_ = why ? why : "";
}

void Controller::setObservationTarget(const Isometry& pose, bool valid) {
  if (!valid || !pose.matrix().allFinite()) return;  // hold the last target, no extrapolation
  observation_->setTarget(pose);
  has_observation_ = true;
}

void Controller::resetObservedObject(const Isometry& pose, const Vector6& velocity) {
  if (!pose.matrix().allFinite() || !velocity.allFinite()) return;
  integrator_.reset(pose, velocity);
}

void Controller::setGraspOffset(const GraspOffset& offset) {
  for (int i = 0; i < numTasks(); ++i)
    if (tasks_[i] == tracking_) setTaskOffset(i, offset);
}

bool Controller::setTaskEnabled(const std::string& name, bool enabled) {
  if (!formulation_.hasTask(name)) return false;
  formulation_.setTaskEnabled(name, enabled);
  return true;
}

bool Controller::setConstraintEnabled(const std::string& name, bool enabled) {
  if (!formulation_.hasConstraint(name)) return false;
  formulation_.setConstraintEnabled(name, enabled);
  return true;
}

void Controller::setPayload(const Payload& payload) { control::setPayload(model_, data_, payload); }

void Controller::clearPayload() { control::clearPayload(model_, data_); }

void Controller::setExternalWrench(const Vector6& wrench) {
  if (wrench.allFinite()) external_wrench_ = wrench;
}

void Controller::setDisturbanceFeedback(double g, bool learn) {
  disturbance_learn_ = learn;
  if (config_.disturbance.compensation == DisturbanceSettings::Compensation::kOff) g = 0.0;
  if (!std::isfinite(g)) return;
  g = std::clamp(g, 0.0, 1.0);
  if (disturbance_gain_ == 0.0 && g > 0.0) disturbance_.reset();
  disturbance_gain_ = g;
}

Vector3 Controller::sensorAcceleration() const {
  return frameDrift(model_, data_, ft_id_).head<3>() + J_ft_.topRows<3>() * qdd_;
}

void Controller::setSpeedScale(double s) {
  if (!std::isfinite(s) || !velocity_limit_) return;
  velocity_limit_->setSpeedScale(std::min(1.0, std::max(1e-3, s)));
}

GraspFrameState Controller::graspFrame() const {
  const ObservedState& obs = integrator_.state();
  const double wrist = data_.q[kArmDofs - 1] - 0.5 * (model_.q_min[kArmDofs - 1] + model_.q_max[kArmDofs - 1]);
  return graspFrameState(obs, obs.acceleration, tracking_->graspOffset(), tcpPose().linear(), wrist);
}

Isometry Controller::tcpPose() const { return framePlacement(model_, data_, tcp_id_); }

Vector6 Controller::tcpVelocity() const { return frameVelocity(model_, data_, tcp_id_); }

}  // namespace handover::control
