#include "control/grasp/clearance.hpp"

#include <algorithm>
#include <limits>

namespace handover::control::grasp {

double segmentDistance(const Vector3& p0, const Vector3& p1, const Vector3& q0, const Vector3& q1) {
  // minimise |p0 + s u - (q0 + t v)| over s, t in [0, 1]
  const Vector3 u = p1 - p0, v = q1 - q0, w = p0 - q0;
  const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
  constexpr double kTiny = 1e-14;
  double s = 0.0, t = 0.0;
  if (a < kTiny && c < kTiny) return w.norm();  // two points
  if (a < kTiny) {
    t = std::clamp(e / c, 0.0, 1.0);
  } else if (c < kTiny) {
    s = std::clamp(-d / a, 0.0, 1.0);
  } else {
    const double den = a * c - b * b;  // 0 for parallel segments: any s works, start at 0
    s = den > kTiny ? std::clamp((b * e - c * d) / den, 0.0, 1.0) : 0.0;
    // best t for that s, then the best s for a clamped t
    t = (b * s + e) / c;
    if (t < 0.0) {
      t = 0.0;
      s = std::clamp(-d / a, 0.0, 1.0);
    } else if (t > 1.0) {
      t = 1.0;
      s = std::clamp((b - d) / a, 0.0, 1.0);
    }
  }
  return (w + s * u - t * v).norm();
}

double segmentBoxDistance(const Vector3& p0, const Vector3& p1, const Vector3& centre, const Matrix3& axes,
                          const Vector3& half) {
  // in the box frame the distance of the segment's point at s is convex in s
  // (a distance to a convex set along a line): golden-section search on [0, 1]
  const Vector3 a = axes.transpose() * (p0 - centre);
  const Vector3 u = axes.transpose() * (p1 - p0);
  auto at = [&](double s) {
    const Vector3 p = a + s * u;
    return (p - p.cwiseMax(-half).cwiseMin(half)).norm();
  };
  constexpr double kInvPhi = 0.6180339887498949;
  constexpr int kIterations = 40;  // the bracket shrinks to 0.618^40 (4e-9) of the segment
  double lo = 0.0, hi = 1.0;
  double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
  double f1 = at(x1), f2 = at(x2);
  for (int i = 0; i < kIterations; ++i) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kInvPhi * (hi - lo);
      f1 = at(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kInvPhi * (hi - lo);
      f2 = at(x2);
    }
  }
  // the ends are candidates too (the minimum may sit at one)
  return std::min({f1, f2, at(0.0), at(1.0)});
}

namespace {

// surface distance of capsule `c` posed by `poses` to obstacle `o` (m, negative: overlap)
double capsuleDistance(const ChainPoses& poses, const Capsule& c, const ObstacleCapsule& o) {
  const Isometry& X = poses.oMb[c.body];
  const double core = o.box_half_extents.isZero()
                          ? segmentDistance(X * c.a, X * c.b, o.a, o.b)
                          : segmentBoxDistance(X * c.a, X * c.b, o.a, o.box_axes, o.box_half_extents);
  return core - c.radius - o.radius;
}

// what the collision constraints keep capsule `c` from obstacle `o` (m): the arm's or the gripper's keep
double keepOf(const Capsule& c, const ObstacleCapsule& o, bool sharing = false) {
  const bool arm = c.role == CapsuleRole::kArm;
  const double shared = arm ? o.keep_arm_sharing : o.keep_gripper_sharing;
  if (sharing && shared >= 0.0) return shared;
  return arm ? o.keep_arm : o.keep_gripper;
}

}  // namespace

double armClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles, int num_obstacles) {
  double best = std::numeric_limits<double>::infinity();
  for (const Capsule& c : model.capsules) {
    for (int k = 0; k < num_obstacles; ++k) {
      const ObstacleCapsule& o = obstacles[k];
      if (o.keep_only || o.held_object || (o.gripper_works_here && c.role == CapsuleRole::kFingertip)) continue;
      best = std::min(best, capsuleDistance(poses, c, o));
    }
  }
  return best;
}

double workZoneClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                         int num_obstacles) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < num_obstacles; ++k) {
    const ObstacleCapsule& o = obstacles[k];
    if (!o.gripper_works_here || o.held_object) continue;
    for (const Capsule& c : model.capsules)
      if (c.role != CapsuleRole::kFingertip) best = std::min(best, capsuleDistance(poses, c, o));
  }
  return best;
}

double heldObjectClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                           int num_obstacles) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < num_obstacles; ++k) {
    const ObstacleCapsule& o = obstacles[k];
    if (!o.held_object) continue;
    for (const Capsule& c : model.capsules) {
      best = std::min(best, capsuleDistance(poses, c, o) - keepOf(c, o));
    }
  }
  return best;
}

double personBodyClearance(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                          int num_obstacles, bool sharing) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < num_obstacles; ++k) {
    const ObstacleCapsule& o = obstacles[k];
    if (o.keep_only || o.held_object) continue;
    for (const Capsule& c : model.capsules) {
      // the gripper works in the person's hand (workZoneClearance); the arm's links keep clear of it
      if (o.gripper_works_here && c.role != CapsuleRole::kArm) continue;
      best = std::min(best, capsuleDistance(poses, c, o) - keepOf(c, o, sharing));
    }
  }
  return best;
}

double keepShortfall(const Model& model, const ChainPoses& poses, const ObstacleCapsule* obstacles,
                     int num_obstacles) {
  double shortfall = 0.0;
  for (int k = 0; k < num_obstacles; ++k) {
    const ObstacleCapsule& o = obstacles[k];
    if (o.gripper_works_here || o.held_object) continue;  // the fingers close in it: workZoneClearance
    for (const Capsule& c : model.capsules) {
      shortfall = std::max(shortfall, keepOf(c, o) - capsuleDistance(poses, c, o));
    }
  }
  return shortfall;
}

double lowestArmPoint(const Model& model, const ChainPoses& poses, int first_body) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Capsule& c : model.capsules) {
    if (c.body < first_body) continue;
    const Isometry& X = poses.oMb[c.body];
    lowest = std::min(lowest, std::min((X * c.a).z(), (X * c.b).z()) - c.radius);
  }
  return lowest;
}

}  // namespace handover::control::grasp
