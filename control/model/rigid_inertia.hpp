// Operations on a body's mass properties (Inertia): moving them to another
// frame and merging two rigid bodies. Header-only, allocation-free, real-time safe.
#pragma once

#include "control/model/model.hpp"

namespace handover::control {

/// Parallel-axis term: inertia of a point mass of 1 kg at offset d, (d.d) I - d d^T.
inline Matrix3 parallelAxis(const Vector3& d) {
  return d.squaredNorm() * Matrix3::Identity() - d * d.transpose();
}

/// `in` given in frame B, returned in frame A, where X = pose of B in A.
inline Inertia transformInertia(const Inertia& in, const Isometry& X) {
  Inertia out;
  out.mass = in.mass;
  out.com = X * in.com;
  out.inertia_com = X.linear() * in.inertia_com * X.linear().transpose();
  return out;
}

/// The rigid union of two bodies given in the same frame.
inline Inertia combineInertia(const Inertia& a, const Inertia& b) {
  Inertia out;
  out.mass = a.mass + b.mass;
  if (out.mass <= 0.0) return out;
  out.com = (a.mass * a.com + b.mass * b.com) / out.mass;
  out.inertia_com = a.inertia_com + a.mass * parallelAxis(a.com - out.com) +
                    b.inertia_com + b.mass * parallelAxis(b.com - out.com);
  return out;
}

}  // namespace handover::control
