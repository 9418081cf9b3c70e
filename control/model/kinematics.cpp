// Forward kinematics, Jacobians and drifts, all in world axes at body origins.
// Revolute joint i turns about an axis through body i's origin, so body
// origins move only by the rotation of their parents.
#include "control/model/algorithms.hpp"
#include "control/model/rigid_inertia.hpp"

namespace handover::control {

void forwardKinematics(const Model& model, Data& data, const Vector7& q, const Vector7& v) {
  data.q = q;
  data.v = v;
  data.oMb[0].setIdentity();
  data.body_velocity[0].setZero();
  data.body_drift[0].setZero();
  data.body_jacobian[0].setZero();
  data.axis_world[0].setZero();

  for (int i = 1; i < kNumBodies; ++i) {
    const int j = i - 1;  // joint index
    const Isometry& parent = data.oMb[j];
    const Matrix3 Rj = parent.linear() * model.joint_placements[j].linear();
    const Vector3 z = Rj * model.joint_axes[j];
    const Vector3 p = parent * model.joint_placements[j].translation();
    data.oMb[i].linear() = Rj * Eigen::AngleAxisd(q[j], model.joint_axes[j]).toRotationMatrix();
    data.oMb[i].translation() = p;
    data.axis_world[i] = z;

    // velocity: parent's, carried over the lever r, plus the joint's rotation
    const Vector3 r = p - parent.translation();
    const Vector3 w_parent = data.body_velocity[j].tail<3>();
    const Vector3 wd_parent = data.body_drift[j].tail<3>();
    data.body_velocity[i].head<3>() = data.body_velocity[j].head<3>() + w_parent.cross(r);
    data.body_velocity[i].tail<3>() = w_parent + z * v[j];
    // drift (qddot = 0): the axis z turns with the parent at w_parent
    data.body_drift[i].head<3>() = data.body_drift[j].head<3>() + wd_parent.cross(r) + w_parent.cross(w_parent.cross(r));
    data.body_drift[i].tail<3>() = wd_parent + w_parent.cross(z * v[j]);

    // Jacobian of body i's origin: column k = [z_k x (p_i - p_k); z_k] for k < i
    Matrix6x7& J = data.body_jacobian[i];
    J.setZero();
    for (int k = 1; k <= i; ++k) {
      const Vector3& zk = data.axis_world[k];
      J.col(k - 1).head<3>() = zk.cross(p - data.oMb[k].translation());
      J.col(k - 1).tail<3>() = zk;
    }
  }

  // mass properties in world axes, for crba / rnea
  for (int i = 0; i < kNumBodies; ++i) {
    const Inertia& in = (i == kArmDofs) ? data.body7_with_payload : model.inertias[i];
    const Matrix3& R = data.oMb[i].linear();
    data.com_world[i] = data.oMb[i] * in.com;
    data.inertia_world[i].noalias() = R * in.inertia_com * R.transpose();
  }
}

Isometry framePlacement(const Model& model, const Data& data, int frame_id) {
  const Frame& f = model.frames[frame_id];
  return data.oMb[f.body] * f.placement;
}

Matrix3 frameRotation(const Model& model, int frame_id, const Vector7& q) {
  const Frame& f = model.frames[frame_id];
  Matrix3 R = Matrix3::Identity();
  for (int j = 0; j < f.body; ++j)
    R = R * model.joint_placements[j].linear() * Eigen::AngleAxisd(q[j], model.joint_axes[j]).toRotationMatrix();
  return R * f.placement.linear();
}

void pointJacobian(const Model&, const Data& data, int body, const Vector3& point_world, Matrix3x7& J) {
  // v_point = v_origin + omega x r  =>  J_lin - [r]x J_ang
  const Vector3 r = point_world - data.oMb[body].translation();
  const Matrix6x7& Jb = data.body_jacobian[body];
  for (int k = 0; k < kArmDofs; ++k) {
    J.col(k) = Jb.col(k).head<3>() + Jb.col(k).tail<3>().cross(r);
  }
}

Vector3 pointDrift(const Model&, const Data& data, int body, const Vector3& point_world) {
  const Vector3 r = point_world - data.oMb[body].translation();
  const Vector3 w = data.body_velocity[body].tail<3>();
  const Vector3 wd = data.body_drift[body].tail<3>();
  return data.body_drift[body].head<3>() + wd.cross(r) + w.cross(w.cross(r));
}

void frameJacobian(const Model& model, const Data& data, int frame_id, Matrix6x7& J) {
  const Frame& f = model.frames[frame_id];
  const Vector3 p = data.oMb[f.body] * f.placement.translation();
  Matrix3x7 Jv;
  pointJacobian(model, data, f.body, p, Jv);
  J.topRows<3>() = Jv;
  J.bottomRows<3>() = data.body_jacobian[f.body].bottomRows<3>();
}

Vector6 frameVelocity(const Model& model, const Data& data, int frame_id) {
  const Frame& f = model.frames[frame_id];
  const Vector3 r = data.oMb[f.body].linear() * f.placement.translation();
  const Vector6& vb = data.body_velocity[f.body];
  Vector6 out;
  out.head<3>() = vb.head<3>() + vb.tail<3>().cross(r);
  out.tail<3>() = vb.tail<3>();
  return out;
}

Vector6 frameDrift(const Model& model, const Data& data, int frame_id) {
  const Frame& f = model.frames[frame_id];
  const Vector3 p = data.oMb[f.body] * f.placement.translation();
  Vector6 out;
  out.head<3>() = pointDrift(model, data, f.body, p);
  out.tail<3>() = data.body_drift[f.body].tail<3>();
  return out;
}

}  // namespace handover::control
