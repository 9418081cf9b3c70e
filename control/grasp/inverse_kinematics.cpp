#include "control/grasp/inverse_kinematics.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "control/grasp/chain_kinematics.hpp"
#include "control/so3.hpp"

namespace handover::control::grasp {

namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// weighted error e = [dp; w * dtheta] and its plain norms
struct PoseResidual {
  Vector6 e;
  double position = 0.0;
  double orientation = 0.0;
};

PoseResidual residual(const Isometry& X, const Isometry& target, double w) {
  PoseResidual r;
  const Vector3 dp = target.translation() - X.translation();
  const Vector3 dtheta = logRotation(target.linear() * X.linear().transpose());
  r.e.head<3>() = dp;
  r.e.tail<3>() = w * dtheta;
  r.position = dp.norm();
  r.orientation = dtheta.norm();
  return r;
}

Vector7 clampToLimits(const Model& model, const Vector7& q, double clearance) {
  Vector7 out;
  for (int i = 0; i < kArmDofs; ++i) {
    // a clearance larger than half the range collapses to the middle
    const double lo = model.q_min[i] + clearance, hi = model.q_max[i] - clearance;
    out[i] = lo <= hi ? std::min(std::max(q[i], lo), hi) : 0.5 * (model.q_min[i] + model.q_max[i]);
  }
  return out;
}

}  // namespace

IkResult solveIk(const Model& model, int frame_id, const Isometry& target, const Vector7& seed,
                 const IkOptions& options) {
  IkResult result;
  ChainPoses poses;
  Matrix6x7 J;
  const double w = options.orientation_weight;
  const Vector7 q_mid = 0.5 * (model.q_min + model.q_max);
  // gradient weights of sum(((q - q_mid) / half_range)^2), scaled so that the
  // narrowest joint moves `nullspace_gain` of its way to the middle
  const Vector7 half_range = 0.5 * (model.q_max - model.q_min);
  const Vector7 limit_weight = (half_range.minCoeff() * half_range.cwiseInverse()).cwiseAbs2();

  Vector7 q = clampToLimits(model, seed, options.limit_clearance);
  chainPoses(model, q, poses);
  PoseResidual r = residual(chainFramePose(model, poses, frame_id), target, w);
  double energy = 0.5 * r.e.squaredNorm();
  double mu = 1.0;  // grows on rejected steps (trust region shrinks), back toward 1 on accepted ones
  double window_start_energy = energy;
  ChainPoses trial_poses;
  for (int it = 0;; ++it) {
    result.q = q;
    result.iterations = it;
    result.position_error = r.position;
    result.orientation_error = r.orientation;
    if (r.position < options.position_tolerance && r.orientation < options.orientation_tolerance) {
      result.converged = true;
      return result;
    }
    if (it >= options.max_iterations) return result;
    if (it > 0 && it % options.stall_window == 0) {
      if (energy > (1.0 - options.stall_ratio) * window_start_energy) return result;
      window_start_energy = energy;
    }

    chainFrameJacobian(model, poses, frame_id, J);
    J.bottomRows<3>() *= w;
    // primary: damped Gauss-Newton step on the weighted pose error, in the
    // 6x6 form (J'J + lambda I)^-1 J' = J' (J J' + lambda I)^-1, whose J J'
    // the null-space projector below shares
    const Matrix6d JJt = J * J.transpose();
    Matrix6d A = JJt;
    A.diagonal().array() += mu * (energy + options.damping);
    // positive definite (lambda > 0): Cholesky without pivoting, the cheapest
    Vector7 dq = J.transpose() * A.llt().solve(r.e);

    // secondary: toward mid-range, inside the (damped) null space of J
    // (not in the last few iterations: its second-order error would keep the
    // task from converging to a tight tolerance)
    const bool near = r.position < 10.0 * options.position_tolerance &&
                      r.orientation < 10.0 * options.orientation_tolerance;
    if (options.nullspace_gain > 0.0 && !near) {
      // a tiny regulariser only: the projector's leak into the task grows with it
      Matrix6d B = JJt;
      B.diagonal().array() += 1e-9;
      const Vector7 toward_mid = options.nullspace_gain * (q_mid - q).cwiseProduct(limit_weight);
      Vector7 dq_null = toward_mid - J.transpose() * B.llt().solve(J * toward_mid);
      // near a singularity the projection is ill-conditioned: a large step
      // here leaves second-order task errors that the next step undoes
      const double n = dq_null.cwiseAbs().maxCoeff();
      const double cap = options.nullspace_max_step / mu;
      if (n > cap) dq_null *= cap / n;
      dq += dq_null;
    }

    // bounded step keeps the linearisation meaningful far from the target
    const double largest = dq.cwiseAbs().maxCoeff();
    if (largest > options.max_step) dq *= options.max_step / largest;
    const Vector7 q_trial = clampToLimits(model, q + dq, options.limit_clearance);
    chainPoses(model, q_trial, trial_poses);
    const PoseResidual r_trial = residual(chainFramePose(model, trial_poses, frame_id), target, w);
    const double trial_energy = 0.5 * r_trial.e.squaredNorm();
    // Levenberg-Marquardt: keep a step only if it lowers the error, else damp more
    if (trial_energy < energy) {
      q = q_trial;
      poses = trial_poses;
      r = r_trial;
      energy = trial_energy;
      mu = std::max(1.0, mu / 3.0);
    } else {
      mu *= 4.0;
    }
  }
}

IkResult solveIkMultiStart(const Model& model, int frame_id, const Isometry& target, const Vector7* seeds,
                           int num_seeds, const IkOptions& options) {
  IkResult best;
  double best_residual = std::numeric_limits<double>::infinity();
  for (int s = 0; s < num_seeds; ++s) {
    const IkResult r = solveIk(model, frame_id, target, seeds[s], options);
    if (r.converged) return r;
    const double w = options.orientation_weight;
    const double residual = r.position_error * r.position_error + w * w * r.orientation_error * r.orientation_error;
    if (residual < best_residual) {
      best_residual = residual;
      best = r;
    }
  }
  return best;
}

void poseError(const Model& model, int frame_id, const Vector7& q, const Isometry& target, double& position_error,
               double& orientation_error) {
  ChainPoses poses;
  chainPoses(model, q, poses);
  const PoseResidual r = residual(chainFramePose(model, poses, frame_id), target, 1.0);
  position_error = r.position;
  orientation_error = r.orientation;
}

}  // namespace handover::control::grasp
