#include "control/collision/collision_distances.hpp"

#include <cmath>
#include <limits>

#include "config/input_error.hpp"
#include "control/model/algorithms.hpp"

namespace handover::control {

namespace {

// twist of a frame re-expressed at another origin (same rigid motion)
Vector6 shiftTwist(const Vector6& twist, const Vector3& from, const Vector3& to) {
  Vector6 t = twist;
  t.head<3>() += twist.tail<3>().cross(to - from);
  return t;
}

// distance from a point to a box (canonical pose X, full edges size); 0 inside
double pointBoxDistance(const Vector3& p, const Isometry& X, const Vector3& size) {
  const Vector3 q = X.inverse(Eigen::Isometry) * p;
  const Vector3 excess = (q.cwiseAbs() - 0.5 * size).cwiseMax(0.0);
  return excess.norm();
}

// The feature of a box that its closest point p lies on: how many of its
// coordinates (box frame) sit at the box's bound: 1 a face, 2 an edge, 3 a
// corner. On an edge, `axis` (world) is the edge's direction (the free
// coordinate's box axis). p is clamped onto the box (shape_distance.cpp), so
// the bound holds to rounding.
int boxFeature(const Vector3& p, const Isometry& X, const Vector3& size, Vector3& axis) {
  const Vector3 q = X.inverse(Eigen::Isometry) * p;
  int on = 0, free_axis = 0;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(std::abs(q[k]) - 0.5 * size[k]) < 1e-7)
      ++on;
    else
      free_axis = k;
  }
  axis = X.linear().col(free_axis);
  return on;
}

void updatePoses(const CollisionModel& cm, CollisionData& cd, const Data& data, const CollisionEnvironment& env) {
  for (std::size_t i = 0; i < cm.bodies.size(); ++i) {
    const CollisionBody& b = cm.bodies[i];
    if (b.isRobot()) cd.body_pose[i] = data.oMb[b.body] * b.local;
  }
  cd.body_pose[cm.table] = cm.bodies[cm.table].local;
  cd.body_twist[cm.table].setZero();

  cd.body_pose[cm.human_hand] = env.hand * cm.bodies[cm.human_hand].local;
  cd.body_twist[cm.human_hand] =
      shiftTwist(env.hand_velocity, env.hand.translation(), cd.body_pose[cm.human_hand].translation());

  auto segment = [&](int idx, const Isometry& X, double length, const Vector6& twist) {
    const double L = std::max(length, 0.0);
    if (cd.shapes.segmentLength(idx) != L) cd.shapes.setSegmentLength(idx, L);
    Isometry C = X;
    C.translation() = X * Vector3(0.0, 0.0, 0.5 * L);
    cd.body_pose[idx] = C;
    cd.body_twist[idx] = shiftTwist(twist, X.translation(), C.translation());
  };
  segment(cm.human_forearm, env.forearm, env.forearm_length, env.forearm_velocity);
  segment(cm.human_upper_arm, env.upper_arm, env.upper_arm_length, env.upper_arm_velocity);
  for (int idx : {cm.human_torso, cm.human_legs, cm.human_head, cm.human_free_arm}) {
    cd.body_pose[idx] = env.torso * cm.bodies[idx].local;
    cd.body_twist[idx].setZero();  // a person standing: the trunk's motion is not estimated
  }
  // the hand's way from its grip point now to the reach's end; the end stays, the start moves
  // with the hand (the twist is taken as zero: the hand's own pairs carry its speed)
  const Vector3 from = env.hand.translation(), way = env.hand_forecast.translation() - from;
  Isometry along = Isometry::Identity();
  along.translation() = from;
  if (way.norm() > 1e-9) along.linear() = Eigen::Quaterniond::FromTwoVectors(Vector3::UnitZ(), way).toRotationMatrix();
  segment(cm.human_hand_forecast, along, way.norm(), Vector6::Zero());
  cd.body_pose[cm.object] = env.object * cm.bodies[cm.object].local;
  cd.body_twist[cm.object] =
      shiftTwist(env.object_velocity, env.object.translation(), cd.body_pose[cm.object].translation());
}

// lower bound of the core-to-core distance from bounding spheres
double coreLowerBound(const CollisionData& cd, const CollisionBody& a, int ia, const CollisionBody& o, int io) {
  const Vector3& ca = cd.body_pose[ia].translation();
  const double ra = 0.5 * cd.shapes.segmentLength(ia);
  if (o.shape.kind == ShapeSpec::Kind::kBox) return pointBoxDistance(ca, cd.body_pose[io], o.shape.size) - ra;
  (void)a;
  return (ca - cd.body_pose[io].translation()).norm() - ra - 0.5 * cd.shapes.segmentLength(io);
}

// d_ddot at qddot = 0 of two cores whose closest points c1 and c2 each lie
// on a point or a line of their body (a capsule's segment end or interior, a
// box's corner or edge), with unit normal n (c1 - c2 = D n), relative
// velocity dv and acceleration da of the two material points at c1 and c2.
// The closest points are not material points: inside a line one slides along
// it at s_dot (from keeping c1 - c2 perpendicular to each line it lies
// inside), and a sliding point meets material that moves differently on a
// turning line (2 s_dot n.(omega x u)); the normal turns with the relative
// velocity of the closest points themselves. Taking them as material points
// (the witness frozen on each body) misses both: for two capsules close to
// parallel the witness slides ten times faster than the bodies move and a
// fast arm gliding along itself sank below sDist while the rows expected it
// to curve away; a finger gliding along a box's edge at 0.45 m/s read
// 6-30 m/s^2 of curving away that a straight edge does not have, and went
// 1.6 cm into the object it was meant to keep 5 mm from. The slide rate is
// held to that of 8 degrees off parallel (exactly parallel lines have no
// unique closest points).
// 1 - cos^2 of 8 degrees: sin^2(8 deg)
constexpr double kMinSlideDeterminant = 0.019369152030840567;

/// A closest point's feature: inside a line of direction u (unit, world), or
/// on a point (in = false).
struct ClosestFeature {
  bool in = false;
  Vector3 u = Vector3::Zero();
};

// a capsule's core: inside its segment, or at an end
ClosestFeature segmentFeature(const CollisionData& cd, int idx, const Vector3& c) {
  const double half = 0.5 * cd.shapes.segmentLength(idx);
  const Isometry& X = cd.body_pose[idx];
  ClosestFeature f;
  f.u = X.linear().col(2);
  f.in = half > 1e-9 && std::abs(f.u.dot(c - X.translation())) < half - 1e-9;
  return f;
}

double featurePairDrift(const ClosestFeature& f1, const Vector3& omega1, const ClosestFeature& f2,
                        const Vector3& omega2, const Vector3& n, double D, const Vector3& dv, const Vector3& da) {
  const bool in1 = D > 1e-9 && f1.in, in2 = D > 1e-9 && f2.in;
  const Vector3& u1 = f1.u;
  const Vector3& u2 = f2.u;
  const Vector3 u1dot = in1 ? Vector3(omega1.cross(u1)) : Vector3::Zero();
  const Vector3 u2dot = in2 ? Vector3(omega2.cross(u2)) : Vector3::Zero();
  // (dv + s_dot u1 - t_dot u2).u_k + D n.u_k_dot = 0 for each line k its closest point lies inside
  double s_dot = 0.0, t_dot = 0.0;
  const double r1 = in1 ? -dv.dot(u1) - D * n.dot(u1dot) : 0.0;
  const double r2 = in2 ? -dv.dot(u2) - D * n.dot(u2dot) : 0.0;
  if (in1 && in2) {
    const double c = u1.dot(u2);
    const double det = std::max(1.0 - c * c, kMinSlideDeterminant);
    // s_dot - c t_dot = r1,  c s_dot - t_dot = r2
    s_dot = (r1 - c * r2) / det;
    t_dot = (c * r1 - r2) / det;
  } else if (in1) {
    s_dot = r1;
  } else if (in2) {
    t_dot = -r2;
  }
  Vector3 wdot = dv;
  if (in1) wdot += s_dot * u1;
  if (in2) wdot -= t_dot * u2;
  const Vector3 tangential = wdot - n * n.dot(wdot);
  const double curvature = D > 1e-9 ? tangential.squaredNorm() / D : 0.0;
  return n.dot(da) + 2.0 * s_dot * n.dot(u1dot) - 2.0 * t_dot * n.dot(u2dot) + curvature;
}

}  // namespace

void updateCollisions(const CollisionModel& cm, CollisionData& cd, const Model& model, const Data& data,
                      const CollisionEnvironment& env) {
  updatePoses(cm, cd, data, env);
  cd.num_active = 0;
  cd.num_narrow = 0;
  const Vector7& qdot = data.v;
  Matrix3x7 J1, J2;
  ShapeDistanceResult sd;

  for (int k = 0; k < cm.numPairs(); ++k) {
    const CollisionPair& pair = cm.pairs[k];
    PairResult& res = cd.results[k];
    res.active = false;
    if (!cd.rule_enabled[pair.rule]) continue;
    const int ia = pair.robot_body, io = pair.other_body;
    const CollisionBody& a = cm.bodies[ia];
    const CollisionBody& o = cm.bodies[io];
    if (o.isPerson() && !env.person_valid) continue;
    if (o.kind == CollisionBodyKind::kHumanTrunk && !env.trunk_valid) continue;
    if (o.kind == CollisionBodyKind::kObject && !env.object_valid) continue;
    if (o.kind == CollisionBodyKind::kHumanHandForecast && !(env.hand_forecast_valid && env.person_valid)) continue;

    // broad phase: skip pairs that cannot come within reach of the damper
    const double radii = a.radius + o.radius + pair.margin;
    const double lower = coreLowerBound(cd, a, ia, o, io) - radii;
    if (lower > pair.damper.i_dist + cm.broadphase_margin) continue;

    // narrow phase on the cores
    ++cd.num_narrow;
    cd.shapes.compute(ia, cd.body_pose[ia], io, cd.body_pose[io], sd);
    Vector3 c1 = sd.p1, c2 = sd.p2;
    double D = sd.distance;
    Vector3 n;
    res.penetrating = !(sd.separated && D > 1e-9);
    if (!res.penetrating) {
      n = (c1 - c2) / D;
    } else {
      if (!sd.separated && o.shape.kind == ShapeSpec::Kind::kBox) {
        // GJK gives no points inside a box: use the segment's centre
        c1 = c2 = cd.body_pose[ia].translation();
      }
      D = 0.0;
      if (cd.has_last_normal[k]) {
        n = cd.last_normal[k];
      } else {
        const Vector3 away = cd.body_pose[ia].translation() - cd.body_pose[io].translation();
        n = away.norm() > 1e-9 ? Vector3(away.normalized()) : Vector3::UnitZ();
      }
    }
    cd.last_normal[k] = n;
    cd.has_last_normal[k] = true;

    res.active = true;
    ++cd.num_active;
    res.core_distance = D;
    res.distance = D - radii;
    res.c_robot = c1;
    res.c_other = c2;
    res.normal = n;
    res.p_robot = c1 - a.radius * n;
    res.p_other = c2 + o.radius * n;

    // velocities and accelerations (at qddot = 0) of the two core points
    pointJacobian(model, data, a.body, c1, J1);
    Vector3 v1 = J1 * qdot;
    Vector3 acc1 = pointDrift(model, data, a.body, c1);
    Vector3 v2, acc2, omega2;
    if (o.isRobot()) {
      pointJacobian(model, data, o.body, c2, J2);
      v2 = J2 * qdot;
      acc2 = pointDrift(model, data, o.body, c2);
      omega2 = data.body_velocity[o.body].tail<3>();
      res.jacobian.noalias() = n.transpose() * (J1 - J2);
    } else {
      const Vector6& tw = cd.body_twist[io];
      omega2 = tw.tail<3>();
      v2 = tw.head<3>() + omega2.cross(c2 - cd.body_pose[io].translation());
      acc2.setZero();  // the person's acceleration is not known
      res.jacobian.noalias() = n.transpose() * J1;
    }
    const Vector3 dv = v1 - v2;
    res.d_dot = n.dot(dv);

    // the normal's rotation: on a box face it turns with the box; on an edge or a corner, and
    // between capsules, with the closest points' relative motion (featurePairDrift)
    const Vector3 omega1 = data.body_velocity[a.body].tail<3>();
    if (o.shape.kind == ShapeSpec::Kind::kBox) {
      ClosestFeature box_feature;  // an edge (a line) or a corner (a point)
      const int on = res.penetrating ? 0 : boxFeature(c2, cd.body_pose[io], o.shape.size, box_feature.u);
      if (on == 1) {
        res.drift = n.dot(acc1 - acc2) + omega2.cross(n).dot(dv);
      } else {
        box_feature.in = on == 2;
        res.drift = featurePairDrift(segmentFeature(cd, ia, c1), omega1, box_feature, omega2, n, D, dv, acc1 - acc2);
      }
    } else {
      res.drift = featurePairDrift(segmentFeature(cd, ia, c1), omega1, segmentFeature(cd, io, c2), omega2, n, D, dv,
                                   acc1 - acc2);
    }
  }
}

void setRuleEnabled(CollisionData& cd, int rule, bool enabled) {
  if (rule >= 0 && rule < static_cast<int>(cd.rule_enabled.size())) cd.rule_enabled[rule] = enabled;
}

void setRuleEnabled(const CollisionModel& cm, CollisionData& cd, const std::string& rule, bool enabled) {
  const int idx = cm.ruleIndex(rule);
  if (idx < 0) {
    std::string known;
    for (const auto& n : cm.rule_names) known += (known.empty() ? "" : ", ") + n;
    throw InputError("collision pair rule '" + rule + "' does not exist (known: " + known + ")");
  }
  setRuleEnabled(cd, idx, enabled);
}

double minPersonDistance(const CollisionModel& cm, const CollisionData& cd) {
  double m = std::numeric_limits<double>::infinity();
  for (int k = 0; k < cm.numPairs(); ++k) {
    if (cd.results[k].active && cm.bodies[cm.pairs[k].other_body].isPerson()) m = std::min(m, cd.results[k].distance);
  }
  return m;
}

NearestPair nearestToSafetyDistance(const CollisionModel& cm, const CollisionData& cd) {
  NearestPair n;
  for (int k = 0; k < cm.numPairs(); ++k) {
    if (!cd.results[k].active) continue;
    const double gap = cd.results[k].distance - cm.pairs[k].damper.s_dist;
    if (n.pair < 0 || gap < n.gap) n = {k, gap};
  }
  return n;
}

}  // namespace handover::control
