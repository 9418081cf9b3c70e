// The QP assembler: owns the variable layout chi = [qddot (7); alphadot_obs (6)]
// (VariableLayout), the task weights and the set of active tasks and
// constraints, and writes them into one QpProblem each cycle:
//
//   H = sum_i w_i A_i' W_i A_i + rho I,    g = -sum_i w_i A_i' W_i b_i
//
// (the minimiser of sum_i 1/2 w_i || W_i^(1/2) (A_i chi - b_i) ||^2 + 1/2 rho ||chi||^2),
// where w_i is the task's scalar weight and W_i = diag(row weights), e.g. the
// per-axis weights of a Cartesian task. Constraints add two-sided rows and
// tighten the variable bounds.
//
// Real-time safety: everything is sized by the constructor. addTask /
// addConstraint / remove* / set* never allocate (they copy a shared_ptr into
// reserved storage), so the state machine may reconfigure the task set inside
// the 1 ms loop; they throw std::invalid_argument on misuse (unknown or
// duplicate name, capacity exceeded), which a correct caller never triggers.
// build() never allocates and never throws.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "control/formulation/constraint.hpp"
#include "control/formulation/control_context.hpp"
#include "control/formulation/task.hpp"
#include "control/qp/qp_problem.hpp"

namespace handover::control {

/// Most rows one task may have (row weights are stored inline).
constexpr int kMaxTaskRows = 16;
using RowWeights = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxTaskRows, 1>;

/// Sizes reserved once by the Formulation constructor.
struct FormulationCapacity {
  int max_tasks = 16;
  int max_constraints = 16;
  int max_constraint_rows = 64;  ///< sum of maxRows() over all constraints held at once
};

class Formulation {
 public:
  explicit Formulation(const FormulationCapacity& capacity = FormulationCapacity());

  // -- configuration (allocation-free after construction) --------------------
  /// Adds an enabled task with a scalar weight (> 0) and unit row weights.
  void addTask(std::shared_ptr<Task> task, double weight);
  /// Same, with per-row weights (size task->rows(), each >= 0).
  void addTask(std::shared_ptr<Task> task, double weight, const Eigen::Ref<const Eigen::VectorXd>& row_weights);
  void addConstraint(std::shared_ptr<Constraint> constraint);
  /// Removes by name; returns false if there was none.
  bool removeTask(const std::string& name);
  bool removeConstraint(const std::string& name);

  bool hasTask(const std::string& name) const { return findTask(name) >= 0; }
  bool hasConstraint(const std::string& name) const { return findConstraint(name) >= 0; }
  /// Disabled tasks/constraints stay registered but contribute nothing.
  void setTaskEnabled(const std::string& name, bool enabled);
  void setConstraintEnabled(const std::string& name, bool enabled);
  bool taskEnabled(const std::string& name) const;
  bool constraintEnabled(const std::string& name) const;
  void setTaskWeight(const std::string& name, double weight);
  double taskWeight(const std::string& name) const;
  void setRowWeights(const std::string& name, const Eigen::Ref<const Eigen::VectorXd>& row_weights);
  const RowWeights& rowWeights(const std::string& name) const;

  /// Tikhonov term rho (>= 0) added to H's diagonal; keeps H positive definite
  /// when the active tasks leave directions of chi free.
  void setRegularisation(double rho);
  double regularisation() const { return rho_; }

  int numTasks() const { return static_cast<int>(tasks_.size()); }
  int numConstraints() const { return static_cast<int>(constraints_.size()); }

  // -- per cycle --------------------------------------------------------------
  /// Sizes a problem for this formulation's capacity (allocates: start-up only).
  void reserveProblem(QpProblem& problem) const;
  /// Writes H, g, the constraint rows and the variable bounds of this cycle.
  /// Real-time safe. `problem` must come from reserveProblem().
  void build(const ControlContext& ctx, QpProblem& problem);

 private:
  struct TaskEntry {
    std::shared_ptr<Task> task;
    double weight = 1.0;
    RowWeights row_weights;
    bool enabled = true;
  };
  struct ConstraintEntry {
    std::shared_ptr<Constraint> constraint;
    bool enabled = true;
  };
  int findTask(const std::string& name) const;
  int findConstraint(const std::string& name) const;
  int taskIndexOrThrow(const std::string& name) const;
  int constraintIndexOrThrow(const std::string& name) const;

  FormulationCapacity capacity_;
  std::vector<TaskEntry> tasks_;
  std::vector<ConstraintEntry> constraints_;
  int constraint_rows_ = 0;  // sum of maxRows() of the registered constraints
  double rho_ = 1e-3;
  Eigen::MatrixXd A_;        // kMaxTaskRows x kNumVars scratch for one task
  Eigen::VectorXd b_;        // kMaxTaskRows
};

}  // namespace handover::control
