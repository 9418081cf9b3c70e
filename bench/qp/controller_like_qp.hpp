// A QP shaped like the controller's (chi = [qddot (7); object accel (6)]),
// built from the Panda's published kinematics and link masses so that the
// Jacobian, mass matrix and gravity torques have realistic structure and scale:
//   tracking    6 rows, weight 1000:  J qdd - X a_obs = b_track (grasp frame follows the object)
//   observation 6 rows, weight 1:     a_obs = b_obs
//   posture     7 rows, weight 5:     qdd = b_post
//   regularisation 1e-6 on every variable
//   torque      7 rows:  -tau_max - h <= M qdd <= tau_max - h
//   collision   20 rows: n' J_p(k) qdd >= lb (velocity-damper-like; some active)
//   bounds      qdd within +-qdd_max (one joint tightened near its limit)
// Only for the benchmark: no part of the controller uses it.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "control/qp/qp_problem.hpp"

namespace handover::bench {

struct PandaLikeModel {
  Eigen::Matrix<double, 6, 7> J;   // tracking Jacobian at the TCP, [linear; angular], world axes
  Eigen::Matrix<double, 7, 7> M;   // joint-space inertia (SPD)
  Eigen::Matrix<double, 7, 1> h;   // gravity torques, N m
  std::array<Eigen::Matrix<double, 3, 7>, 7> Jp;  // position Jacobians of the link centres of mass
};

/// Kinematics by the modified DH table of the Panda; inertia by summing link
/// masses at their centres of mass plus their rotational inertia.
inline PandaLikeModel pandaLikeModel(const Eigen::Matrix<double, 7, 1>& q) {
  const double a[8] = {0, 0, 0, 0.0825, -0.0825, 0, 0.088, 0};
  const double d[8] = {0.333, 0, 0.316, 0, 0.384, 0, 0, 0.107};
  const double alpha[8] = {0, -M_PI / 2, M_PI / 2, M_PI / 2, -M_PI / 2, M_PI / 2, M_PI / 2, 0};
  const double mass[7] = {4.97, 0.65, 3.23, 3.59, 1.23, 1.67, 0.74 + 0.73};
  const double com[7][3] = {{0.0039, 0.0021, -0.0476}, {-0.0031, -0.0287, 0.0035},
                            {0.0275, 0.0393, -0.0665}, {-0.0532, 0.1044, 0.0275},
                            {-0.0120, 0.0411, -0.0384}, {0.0601, -0.0141, -0.0105},
                            {0.0105, -0.0043, 0.0616}};
  const double inertia[7] = {0.02, 0.028, 0.037, 0.026, 0.035, 0.004, 0.012};
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  std::array<Eigen::Vector3d, 7> z, o;
  std::array<Eigen::Isometry3d, 7> frames;
  for (int i = 0; i < 8; ++i) {
    Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
    step.rotate(Eigen::AngleAxisd(alpha[i], Eigen::Vector3d::UnitX()));
    step.translate(Eigen::Vector3d(a[i], 0, 0));
    if (i < 7) step.rotate(Eigen::AngleAxisd(q[i], Eigen::Vector3d::UnitZ()));
    step.translate(Eigen::Vector3d(0, 0, d[i]));
    T = T * step;
    if (i < 7) {
      frames[i] = T;
      z[i] = T.linear().col(2);
      o[i] = T.translation();
    }
  }
  const Eigen::Vector3d tcp = T * Eigen::Vector3d(0, 0, 0.1034);
  PandaLikeModel m;
  for (int j = 0; j < 7; ++j) {
    m.J.block<3, 1>(0, j) = z[j].cross(tcp - o[j]);
    m.J.block<3, 1>(3, j) = z[j];
  }
  m.M.setZero();
  m.h.setZero();
  for (int k = 0; k < 7; ++k) {
    const Eigen::Vector3d c = frames[k] * Eigen::Vector3d(com[k][0], com[k][1], com[k][2]);
    Eigen::Matrix<double, 3, 7> Jv = Eigen::Matrix<double, 3, 7>::Zero();
    Eigen::Matrix<double, 3, 7> Jw = Eigen::Matrix<double, 3, 7>::Zero();
    for (int j = 0; j <= k; ++j) {
      Jv.col(j) = z[j].cross(c - o[j]);
      Jw.col(j) = z[j];
    }
    m.Jp[k] = Jv;
    m.M += mass[k] * Jv.transpose() * Jv + inertia[k] * Jw.transpose() * Jw;
    m.h += mass[k] * Jv.transpose() * Eigen::Vector3d(0, 0, 9.81);
  }
  m.M.diagonal().array() += 0.01;  // rotor inertia seen through the gears
  return m;
}

/// Fills `p` (reserved 13 x 0 x 27) for phase `s` in [0, 2 pi): the tracking
/// and posture references rotate with s, so consecutive phases differ slightly
/// and the sequence is periodic.
inline void controllerLikeQp(double s, handover::control::QpProblem& p) {
  using Vec7 = Eigen::Matrix<double, 7, 1>;
  using Vec6 = Eigen::Matrix<double, 6, 1>;
  Vec7 q;
  q << 0.1 * std::sin(s), -0.785 + 0.1 * std::cos(s), 0.0, -2.356, 0.0, 1.571, 0.785;
  const PandaLikeModel m = pandaLikeModel(q);
  const int n = 13;
  p.n = n;
  p.n_eq = 0;
  Eigen::Matrix<double, 6, 13> At = Eigen::Matrix<double, 6, 13>::Zero();
  At.leftCols<7>() = m.J;
  // grasp frame 5 cm from the object origin: a_grasp = a_obj + omegadot x r
  At.rightCols<6>() = -Eigen::Matrix<double, 6, 6>::Identity();
  const Eigen::Vector3d r(0.0, 0.0, 0.05);
  Eigen::Matrix3d rx;
  rx << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  At.block<3, 3>(0, 10) = rx;  // -(omegadot x r) = r x omegadot
  Vec6 bt;
  // an aggressive approach (the object is still far): several limits bind
  bt << 20.0 * std::cos(s), 12.0 * std::sin(s), -8.0, 12.0 * std::sin(2 * s), 10.0, -12.0 * std::cos(s);
  Eigen::Matrix<double, 6, 13> Ao = Eigen::Matrix<double, 6, 13>::Zero();
  Ao.rightCols<6>().setIdentity();
  Vec6 bo;
  bo << -2.0 * std::sin(s), 1.5 * std::cos(s), 0.5, 0.2, -0.1 * std::sin(s), 0.05;
  Eigen::Matrix<double, 7, 13> Ap = Eigen::Matrix<double, 7, 13>::Zero();
  Ap.leftCols<7>().setIdentity();
  Vec7 bp = -5.0 * (q - Vec7(0, -0.785, 0, -2.356, 0, 1.571, 0.785));
  const double wt = 1000.0, wo = 1.0, wp = 5.0;
  p.H = wt * At.transpose() * At + wo * Ao.transpose() * Ao + wp * Ap.transpose() * Ap;
  p.H.diagonal().array() += 1e-6;
  p.g = -(wt * At.transpose() * bt + wo * Ao.transpose() * bo + wp * Ap.transpose() * bp);

  // torque limits: -tau_max <= M qdd + h <= tau_max
  const double tau_max[7] = {87, 87, 87, 87, 12, 12, 12};
  p.C.topRows(27).setZero();
  for (int i = 0; i < 7; ++i) {
    p.C.block(i, 0, 1, 7) = m.M.row(i);
    p.c_lb[i] = -tau_max[i] - m.h[i];
    p.c_ub[i] = tau_max[i] - m.h[i];
  }
  // collision-like rows: normal directions on the link centres; deterministic
  // "distances" make a few of them bind. Every lb <= 0, so qdd = 0 stays
  // feasible (like a velocity damper when the arm is at rest).
  std::mt19937 rng(12345);
  std::normal_distribution<double> nd(0.0, 1.0);
  for (int i = 0; i < 20; ++i) {
    Eigen::Vector3d nrm(nd(rng), nd(rng), nd(rng));
    nrm.normalize();
    const int link = 2 + i % 5;
    const int row = 7 + i;
    p.C.block(row, 0, 1, 7) = nrm.transpose() * m.Jp[link];
    p.c_lb[row] = i % 3 == 0 ? -0.1 + 0.08 * std::sin(s + i) : -20.0 + std::sin(s + i);
    p.c_ub[row] = std::numeric_limits<double>::infinity();
  }
  p.n_in = 27;
  const double qdd_max[7] = {15, 7.5, 10, 12.5, 15, 20, 20};
  for (int j = 0; j < 7; ++j) {
    p.x_lb[j] = -qdd_max[j];
    p.x_ub[j] = qdd_max[j];
  }
  p.x_ub[3] = 0.2;  // joint 4 close to its upper position limit
}

}  // namespace handover::bench
