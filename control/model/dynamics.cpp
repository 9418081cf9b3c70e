// Joint-space dynamics in world axes, reusing forwardKinematics' poses:
// CRBA with composite bodies (mass, com, inertia about the com) and a
// Newton-Euler pass (RNEA). Both allocation-free.
#include <array>

#include "control/model/algorithms.hpp"
#include "control/model/rigid_inertia.hpp"

namespace handover::control {
namespace {

// Newton-Euler with joint accelerations a and velocities v (world axes).
// Gravity enters as a base acceleration -g. Body states go to data scratch.
Vector7 newtonEuler(const Model& model, Data& data, const Vector7& v, const Vector7& a, bool with_gravity) {
  // forward: angular velocity / acceleration and linear acceleration of each origin
  Vector3 w = Vector3::Zero();
  Vector3 wd = Vector3::Zero();
  Vector3 acc = with_gravity ? Vector3(-model.gravity) : Vector3::Zero();
  for (int i = 1; i < kNumBodies; ++i) {
    const Vector3 r = data.oMb[i].translation() - data.oMb[i - 1].translation();
    const Vector3& z = data.axis_world[i];
    acc += wd.cross(r) + w.cross(w.cross(r));
    wd += w.cross(z * v[i - 1]) + z * a[i - 1];
    w += z * v[i - 1];
    data.scratch_v[i].head<3>() = acc;  // origin acceleration
    data.scratch_v[i].tail<3>() = wd;
    data.scratch_a[i].tail<3>() = w;
  }
  // backward: wrench [force; moment about the body origin] each joint transmits
  Vector3 f = Vector3::Zero(), n = Vector3::Zero();
  Vector7 tau;
  for (int i = kNumBodies - 1; i >= 1; --i) {
    const Inertia& in = (i == kArmDofs) ? data.body7_with_payload : model.inertias[i];
    const Vector3& p = data.oMb[i].translation();
    const Vector3 c = data.com_world[i] - p;
    const Vector3 wi = data.scratch_a[i].tail<3>();
    const Vector3 wdi = data.scratch_v[i].tail<3>();
    const Vector3 a_com = data.scratch_v[i].head<3>() + wdi.cross(c) + wi.cross(wi.cross(c));
    const Matrix3& I = data.inertia_world[i];
    const Vector3 F = in.mass * a_com;
    const Vector3 N = I * wdi + wi.cross(I * wi);
    if (i < kNumBodies - 1) {
      n += (data.oMb[i + 1].translation() - p).cross(f);  // child's force, moved to this origin
    }
    f += F;
    n += N + c.cross(F);
    tau[i - 1] = data.axis_world[i].dot(n);
  }
  return tau;
}

}  // namespace

void crba(const Model& model, Data& data) {
  // composite of bodies i..7: mass, world com, world inertia about that com
  double m_c = 0.0;
  Vector3 c_c = Vector3::Zero();
  Matrix3 I_c = Matrix3::Zero();
  for (int i = kNumBodies - 1; i >= 1; --i) {
    const double m_i = (i == kArmDofs) ? data.body7_with_payload.mass : model.inertias[i].mass;
    const double m = m_c + m_i;
    const Vector3 c = m > 0.0 ? Vector3((m_c * c_c + m_i * data.com_world[i]) / m) : data.com_world[i];
    I_c = I_c + m_c * parallelAxis(c_c - c) + data.inertia_world[i] + m_i * parallelAxis(data.com_world[i] - c);
    m_c = m;
    c_c = c;

    // unit rate of joint i moves the composite: force F at its com, moment N
    const Vector3& z = data.axis_world[i];
    const Vector3 F = m_c * z.cross(c_c - data.oMb[i].translation());
    const Vector3 N = I_c * z;
    for (int j = 1; j <= i; ++j) {
      const Vector3 moment = N + (c_c - data.oMb[j].translation()).cross(F);
      data.M(j - 1, i - 1) = data.axis_world[j].dot(moment);
      data.M(i - 1, j - 1) = data.M(j - 1, i - 1);
    }
  }
}

Vector7 rnea(const Model& model, Data& data, const Vector7& a) {
  return newtonEuler(model, data, data.v, a, true);
}

void gravityJacobian(const Model& model, const Data& data, Matrix7& dg_dq) {
  // g_j = a_j . (r_j x gamma), r_j = sum_{k>=j} m_k (c_k - p_j), gamma = -gravity:
  // the moment about joint j's axis of the weight of everything beyond it.
  const Vector3 gamma = -model.gravity;
  std::array<Vector3, kNumBodies> r;  // r_j, world axes, kg m
  double mass = 0.0;
  Vector3 first_moment = Vector3::Zero();  // sum m_k c_k beyond and at j
  for (int j = kNumBodies - 1; j >= 1; --j) {
    const double m = (j == kArmDofs) ? data.body7_with_payload.mass : model.inertias[j].mass;
    mass += m;
    first_moment += m * data.com_world[j];
    r[j] = first_moment - mass * data.oMb[j].translation();
  }
  for (int j = 1; j < kNumBodies; ++j) {
    const Vector3& a_j = data.axis_world[j];
    for (int i = 1; i < kNumBodies; ++i) {
      const Vector3& a_i = data.axis_world[i];
      if (i > j) {
        // joint i turns only the mass beyond it: r_j changes by a_i x r_i
        dg_dq(j - 1, i - 1) = a_j.dot(a_i.cross(r[i]).cross(gamma));
      } else {
        // joint i (at or before j) turns axis j and its lever together
        dg_dq(j - 1, i - 1) = a_i.cross(a_j).dot(r[j].cross(gamma)) + a_j.dot(a_i.cross(r[j]).cross(gamma));
      }
    }
  }
}

void computeAll(const Model& model, Data& data, const Vector7& q, const Vector7& v) {
  forwardKinematics(model, data, q, v);
  crba(model, data);
  const Vector7 zero = Vector7::Zero();
  data.h = newtonEuler(model, data, v, zero, true);
  data.g = newtonEuler(model, data, zero, zero, true);
}

}  // namespace handover::control
