#include "scenes/human/two_link_arm.hpp"

#include <algorithm>
#include <cmath>

namespace handover::human {

namespace {

// unit vector of v with its component along unit u removed, or zero if tiny
Eigen::Vector3d perpendicular(const Eigen::Vector3d& v, const Eigen::Vector3d& u) {
  const Eigen::Vector3d p = v - v.dot(u) * u;
  const double n = p.norm();
  return n > 1e-6 ? Eigen::Vector3d(p / n) : Eigen::Vector3d::Zero();
}

Eigen::Isometry3d frameAlong(const Eigen::Vector3d& origin, const Eigen::Vector3d& z,
                             const Eigen::Vector3d& x_hint) {
  Eigen::Vector3d x = perpendicular(x_hint, z);
  if (x.isZero()) x = perpendicular(Eigen::Vector3d::UnitX(), z);
  if (x.isZero()) x = perpendicular(Eigen::Vector3d::UnitY(), z);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear().col(0) = x;
  T.linear().col(1) = z.cross(x);
  T.linear().col(2) = z;
  T.translation() = origin;
  return T;
}

}  // namespace

ArmPlacement placeArm(const Eigen::Vector3d& shoulder, const Eigen::Vector3d& grip_target,
                      const ArmLengths& lengths, const Eigen::Vector3d& elbow_hint) {
  ArmPlacement out;
  const double a = lengths.upper_arm;
  const double b = lengths.forearm + lengths.wrist_to_grip;
  out.shoulder = shoulder;

  Eigen::Vector3d to_target = grip_target - shoulder;
  double d = to_target.norm();
  const Eigen::Vector3d u = d > 1e-9 ? Eigen::Vector3d(to_target / d) : Eigen::Vector3d(-Eigen::Vector3d::UnitZ());

  // too far: the arm points straight at the target and falls short
  if (d > a + b) {
    out.reached = false;
    d = a + b;
  }
  // too close to fold: the nearest the grip point can come is |a - b|
  if (d < std::abs(a - b)) {
    out.reached = false;
    d = std::abs(a - b);
  }
  const Eigen::Vector3d grip = shoulder + d * u;

  // elbow circle: centre along u at x from the shoulder, radius r
  const double x = std::clamp((a * a - b * b + d * d) / (2.0 * std::max(d, 1e-9)), -a, a);
  const double r = std::sqrt(std::max(0.0, a * a - x * x));
  Eigen::Vector3d e = perpendicular(elbow_hint, u);
  if (e.isZero()) e = perpendicular(-Eigen::Vector3d::UnitZ(), u);
  if (e.isZero()) e = perpendicular(Eigen::Vector3d::UnitX(), u);
  out.elbow = shoulder + x * u + r * e;

  const Eigen::Vector3d fore = grip - out.elbow;
  const Eigen::Vector3d fore_dir = fore.norm() > 1e-9 ? Eigen::Vector3d(fore.normalized()) : u;
  out.wrist = out.elbow + lengths.forearm * fore_dir;
  out.grip = out.elbow + b * fore_dir;

  // x axes normal to the arm's plane, so both links share it
  const Eigen::Vector3d upper_dir = (out.elbow - shoulder) / a;
  Eigen::Vector3d normal = upper_dir.cross(fore_dir);
  if (normal.norm() < 1e-6) normal = upper_dir.cross(e);
  out.upper_arm = frameAlong(shoulder, upper_dir, normal);
  out.forearm = frameAlong(out.elbow, fore_dir, normal);
  return out;
}

}  // namespace handover::human
