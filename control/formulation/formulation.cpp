#include "control/formulation/formulation.hpp"

#include <cmath>
#include <stdexcept>

namespace handover::control {

Formulation::Formulation(const FormulationCapacity& capacity)
    : capacity_(capacity), A_(kMaxTaskRows, kNumVars), b_(kMaxTaskRows) {
  if (capacity.max_tasks < 0 || capacity.max_constraints < 0 || capacity.max_constraint_rows < 0)
    throw std::invalid_argument("Formulation: negative capacity");
  tasks_.reserve(capacity.max_tasks);
  constraints_.reserve(capacity.max_constraints);
  A_.setZero();
  b_.setZero();
}

int Formulation::findTask(const std::string& name) const {
  for (std::size_t i = 0; i < tasks_.size(); ++i)
    if (tasks_[i].task->name() == name) return static_cast<int>(i);
  return -1;
}

int Formulation::findConstraint(const std::string& name) const {
  for (std::size_t i = 0; i < constraints_.size(); ++i)
    if (constraints_[i].constraint->name() == name) return static_cast<int>(i);
  return -1;
}

int Formulation::taskIndexOrThrow(const std::string& name) const {
  const int i = findTask(name);
  if (i < 0) throw std::invalid_argument("Formulation: no task named '" + name + "'");
  return i;
}

int Formulation::constraintIndexOrThrow(const std::string& name) const {
  const int i = findConstraint(name);
  if (i < 0) throw std::invalid_argument("Formulation: no constraint named '" + name + "'");
  return i;
}

void Formulation::addTask(std::shared_ptr<Task> task, double weight) {
  if (!task) throw std::invalid_argument("Formulation::addTask: null task");
  const int r = task->rows();
  if (r < 0 || r > kMaxTaskRows)
    throw std::invalid_argument("Formulation::addTask: task '" + task->name() + "' has too many rows");
  RowWeights ones = RowWeights::Ones(r);
  addTask(std::move(task), weight, ones);
}

void Formulation::addTask(std::shared_ptr<Task> task, double weight,
                          const Eigen::Ref<const Eigen::VectorXd>& row_weights) {
  if (!task) throw std::invalid_argument("Formulation::addTask: null task");
  const std::string& name = task->name();
  if (findTask(name) >= 0) throw std::invalid_argument("Formulation::addTask: duplicate task '" + name + "'");
  if (static_cast<int>(tasks_.size()) >= capacity_.max_tasks)
    throw std::invalid_argument("Formulation::addTask: capacity exceeded adding '" + name + "'");
  const int r = task->rows();
  if (r < 0 || r > kMaxTaskRows)
    throw std::invalid_argument("Formulation::addTask: task '" + name + "' has too many rows");
  if (!(std::isfinite(weight) && weight >= 0.0))
    throw std::invalid_argument("Formulation::addTask: bad weight for '" + name + "'");
  TaskEntry e;
  e.task = std::move(task);
  e.weight = weight;
  tasks_.push_back(std::move(e));  // capacity reserved: no allocation
  try {
    setRowWeights(name, row_weights);
  } catch (...) {
    tasks_.pop_back();
    throw;
  }
}

void Formulation::addConstraint(std::shared_ptr<Constraint> constraint) {
  if (!constraint) throw std::invalid_argument("Formulation::addConstraint: null constraint");
  const std::string& name = constraint->name();
  if (findConstraint(name) >= 0)
    throw std::invalid_argument("Formulation::addConstraint: duplicate constraint '" + name + "'");
  if (static_cast<int>(constraints_.size()) >= capacity_.max_constraints ||
      constraint_rows_ + constraint->maxRows() > capacity_.max_constraint_rows)
    throw std::invalid_argument("Formulation::addConstraint: capacity exceeded adding '" + name + "'");
  constraint_rows_ += constraint->maxRows();
  constraints_.push_back(ConstraintEntry{std::move(constraint), true});
}

bool Formulation::removeTask(const std::string& name) {
  const int i = findTask(name);
  if (i < 0) return false;
  tasks_.erase(tasks_.begin() + i);  // shifts, never allocates
  return true;
}

bool Formulation::removeConstraint(const std::string& name) {
  const int i = findConstraint(name);
  if (i < 0) return false;
  constraint_rows_ -= constraints_[i].constraint->maxRows();
  constraints_.erase(constraints_.begin() + i);
  return true;
}

void Formulation::setTaskEnabled(const std::string& name, bool enabled) {
  tasks_[taskIndexOrThrow(name)].enabled = enabled;
}

void Formulation::setConstraintEnabled(const std::string& name, bool enabled) {
  constraints_[constraintIndexOrThrow(name)].enabled = enabled;
}

bool Formulation::taskEnabled(const std::string& name) const { return tasks_[taskIndexOrThrow(name)].enabled; }

bool Formulation::constraintEnabled(const std::string& name) const {
  return constraints_[constraintIndexOrThrow(name)].enabled;
}

void Formulation::setTaskWeight(const std::string& name, double weight) {
  if (!(std::isfinite(weight) && weight >= 0.0))
    throw std::invalid_argument("Formulation::setTaskWeight: bad weight for '" + name + "'");
  tasks_[taskIndexOrThrow(name)].weight = weight;
}

double Formulation::taskWeight(const std::string& name) const { return tasks_[taskIndexOrThrow(name)].weight; }

void Formulation::setRowWeights(const std::string& name, const Eigen::Ref<const Eigen::VectorXd>& row_weights) {
  TaskEntry& e = tasks_[taskIndexOrThrow(name)];
  if (row_weights.size() != e.task->rows())
    throw std::invalid_argument("Formulation::setRowWeights: '" + name + "' needs " +
                                std::to_string(e.task->rows()) + " row weights");
  for (Eigen::Index i = 0; i < row_weights.size(); ++i)
    if (!(std::isfinite(row_weights[i]) && row_weights[i] >= 0.0))
      throw std::invalid_argument("Formulation::setRowWeights: bad row weight for '" + name + "'");
  e.row_weights = row_weights;  // inline storage, no allocation
}

const RowWeights& Formulation::rowWeights(const std::string& name) const {
  return tasks_[taskIndexOrThrow(name)].row_weights;
}

void Formulation::setRegularisation(double rho) {
  if (!(std::isfinite(rho) && rho >= 0.0)) throw std::invalid_argument("Formulation: bad regularisation");
  rho_ = rho;
}

void Formulation::reserveProblem(QpProblem& problem) const {
  problem.reserve(kNumVars, 0, capacity_.max_constraint_rows);
}

void Formulation::build(const ControlContext& ctx, QpProblem& problem) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  problem.n = kNumVars;
  problem.n_eq = 0;
  problem.H.setZero();
  problem.H.diagonal().setConstant(rho_);
  problem.g.setZero();

  // tasks: accumulate w * A' W A and -w * A' W b one row at a time (rank-1
  // updates on a 13 x 13 matrix: cheap, and no temporaries)
  for (TaskEntry& e : tasks_) {
    if (!e.enabled || e.weight == 0.0) continue;
    const int r = e.task->rows();
    auto A = A_.topRows(r);
    auto b = b_.head(r);
    A.setZero();
    b.setZero();
    e.task->compute(ctx, A, b);
    for (int i = 0; i < r; ++i) {
      const double w = e.weight * e.row_weights[i];
      if (w == 0.0) continue;
      for (int k = 0; k < kNumVars; ++k) {
        const double wa = w * A(i, k);
        if (wa == 0.0) continue;
        for (int j = k; j < kNumVars; ++j) problem.H(j, k) += wa * A(i, j);
        problem.g[k] -= wa * b[i];
      }
    }
  }
  // mirror the lower triangle
  for (int k = 0; k < kNumVars; ++k)
    for (int j = k + 1; j < kNumVars; ++j) problem.H(k, j) = problem.H(j, k);

  // constraints: rows stacked in registration order, bounds only tightened
  problem.x_lb.setConstant(-kInf);
  problem.x_ub.setConstant(kInf);
  int n_in = 0;
  for (ConstraintEntry& e : constraints_) {
    if (!e.enabled) continue;
    const int m = e.constraint->maxRows();
    if (m == 0) {
      // bounds only: hand over empty row blocks
      e.constraint->compute(ctx, problem.C.middleRows(n_in, 0), problem.c_lb.segment(n_in, 0),
                            problem.c_ub.segment(n_in, 0), problem.x_lb, problem.x_ub);
      continue;
    }
    auto C = problem.C.middleRows(n_in, m);
    C.setZero();
    problem.c_lb.segment(n_in, m).setConstant(-kInf);
    problem.c_ub.segment(n_in, m).setConstant(kInf);
    int used = e.constraint->compute(ctx, C, problem.c_lb.segment(n_in, m), problem.c_ub.segment(n_in, m),
                                     problem.x_lb, problem.x_ub);
    if (used < 0) used = 0;
    if (used > m) used = m;
    problem.soft_in.segment(n_in, used).setConstant(e.constraint->soft() ? 1 : 0);
    n_in += used;
  }
  problem.n_in = n_in;
}

}  // namespace handover::control
