#include "control/qp/qp_solver.hpp"

#include <cmath>
#include <string>

#include "config/input_error.hpp"

namespace handover::control {

void validate(const QpSolverOptions& options) {
  if (options.max_iterations < 1) {
    throw InputError("qp solver option max_iterations=" + std::to_string(options.max_iterations) +
                     " must be >= 1");
  }
  if (!(options.tolerance > 0.0) || !(options.tolerance < 1e-2)) {
    throw InputError("qp solver option tolerance=" + std::to_string(options.tolerance) +
                     " must be in (0, 1e-2)");
  }
}

const char* toString(QpRowKind kind) {
  switch (kind) {
    case QpRowKind::kEquality: return "equality";
    case QpRowKind::kRowLower: return "row_lower";
    case QpRowKind::kRowUpper: return "row_upper";
    case QpRowKind::kRowFixed: return "row_fixed";
    case QpRowKind::kBoundLower: return "bound_lower";
    case QpRowKind::kBoundUpper: return "bound_upper";
    case QpRowKind::kBoundFixed: return "bound_fixed";
  }
  return "unknown";
}

}  // namespace handover::control
