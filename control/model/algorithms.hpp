// Rigid-body algorithms over Model/Data, as free functions.
// All are real-time safe (no allocation, no exceptions) once Data exists,
// except where noted. Frames: world axes unless said otherwise; spatial
// 6-vectors are [linear; angular]; units SI.
#pragma once

#include "control/model/model.hpp"

namespace handover::control {

/// Body poses, velocities, Jacobians and drifts (J*qdot derivative at qddot=0).
void forwardKinematics(const Model& model, Data& data, const Vector7& q, const Vector7& v);

/// Everything a control cycle needs, computed once: forwardKinematics, M (CRBA)
/// and h, g (RNEA). Tasks and constraints then only read Data.
void computeAll(const Model& model, Data& data, const Vector7& q, const Vector7& v);

/// World pose of a frame (requires forwardKinematics).
Isometry framePlacement(const Model& model, const Data& data, int frame_id);

/// World orientation of a frame at q, from the joint rotations alone (no
/// Data, no velocities): for questions about other configurations than the
/// cycle's, e.g. the way the TCP turns along a joint path. Real-time safe.
Matrix3 frameRotation(const Model& model, int frame_id, const Vector7& q);

/// 6x7 Jacobian of a frame: rows [linear velocity of the frame origin; angular
/// velocity], both in world axes (requires forwardKinematics).
void frameJacobian(const Model& model, const Data& data, int frame_id, Matrix6x7& J);

/// [v_origin; omega] of a frame, world axes.
Vector6 frameVelocity(const Model& model, const Data& data, int frame_id);

/// Jdot*qdot of frameJacobian: classical acceleration [a_origin; omegadot] of
/// the frame at qddot = 0, world axes.
Vector6 frameDrift(const Model& model, const Data& data, int frame_id);

/// 3x7 Jacobian of the linear velocity of a point fixed on `body`, the point
/// given in world coordinates at the current configuration.
void pointJacobian(const Model& model, const Data& data, int body, const Vector3& point_world, Matrix3x7& J);

/// Jdot*qdot of pointJacobian: classical acceleration of that body-fixed point at qddot = 0.
Vector3 pointDrift(const Model& model, const Data& data, int body, const Vector3& point_world);

/// Joint-space mass matrix into data.M (CRBA); needs forwardKinematics at q.
void crba(const Model& model, Data& data);

/// Inverse dynamics tau = M(q) a + C(q, v) v + g(q) (RNEA), including the payload.
/// Uses data's body poses: call forwardKinematics(q, v) first.
Vector7 rnea(const Model& model, Data& data, const Vector7& a);

/// d g / d q (N m / rad), column i = the change of the gravity torques Data::g
/// per radian of joint i, payload included; analytic (each joint's turn moves
/// the mass beyond it). Needs forwardKinematics at q. Real-time safe.
void gravityJacobian(const Model& model, const Data& data, Matrix7& dg_dq);

/// Attaches / removes the held object's mass to body 7 (affects M, h, g from the next computeAll).
/// Real-time safe for a valid payload; throws handover::InputError for a negative or
/// non-finite mass, com or inertia. A new payload replaces the previous one.
void setPayload(const Model& model, Data& data, const Payload& payload);
void clearPayload(const Model& model, Data& data);

}  // namespace handover::control
