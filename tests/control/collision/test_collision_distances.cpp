// Distances, Jacobian rows and drifts checked against numerical
// differentiation (Crocoddyl style) for robot-table, robot-person and
// robot-robot pairs at random configurations.
#include <gtest/gtest.h>

#include "collision_test_util.hpp"
#include "control/collision/collision_distances.hpp"

using namespace handover::control;
using namespace handover::control::testing;

namespace {

enum class Kind { kTable, kPerson, kRobot };

struct Fixture {
  const Model& m = pandaModel();
  CollisionModel cm = buildCollisionModel(m, wideConfig());
  CollisionData cd{cm};
  Data data{m};

  Kind kindOf(int k) const {
    const CollisionBody& o = cm.bodies[cm.pairs[k].other_body];
    return o.isRobot() ? Kind::kRobot : o.isPerson() ? Kind::kPerson : Kind::kTable;
  }
  const PairResult& at(const Vector7& q, const Vector7& v, const CollisionEnvironment& env, int k) {
    forwardKinematics(m, data, q, v);
    updateCollisions(cm, cd, m, data, env);
    return cd.results[k];
  }
  // the arm at (q, v) and a person whose hand is `offset` from the TCP (into `env`): the pairs
  std::vector<PairResult> personNearTcp(const Vector7& q, const Vector7& v, const Vector3& offset, std::mt19937& rng,
                                        CollisionEnvironment& env) {
    forwardKinematics(m, data, q, v);
    env = personAt(framePlacement(m, data, m.frameId("tcp")).translation() + offset, rng);
    updateCollisions(cm, cd, m, data, env);
    return cd.results;
  }
  // usable for differentiation: separated cores, not touching the surfaces
  bool smooth(const PairResult& r) const { return r.active && !r.penetrating && r.core_distance > 5e-3; }
};

}  // namespace

TEST(CollisionDistances, JacobianMatchesFiniteDifferenceOfDistance) {
  Fixture f;
  std::mt19937 rng(42);
  int tested[3] = {0, 0, 0};
  const double h = 1e-6;
  for (int trial = 0; trial < 25; ++trial) {
    const Vector7 q = randomConfiguration(f.m, rng);
    forwardKinematics(f.m, f.data, q, Vector7::Zero());
    const Vector3 tcp = framePlacement(f.m, f.data, f.m.frameId("tcp")).translation();
    const CollisionEnvironment env = personAt(tcp + Vector3(0.15, 0.05, 0.0), rng);
    updateCollisions(f.cm, f.cd, f.m, f.data, env);
    const std::vector<PairResult> base = f.cd.results;
    for (int k = 0; k < f.cm.numPairs(); ++k) {
      const PairResult& r0 = base[k];
      if (!f.smooth(r0)) continue;
      // geometry of the result itself
      EXPECT_NEAR(r0.normal.norm(), 1.0, 1e-12);
      const double surface_gap = r0.distance + f.cm.pairs[k].margin;
      EXPECT_NEAR((r0.p_robot - r0.p_other).dot(r0.normal), surface_gap, 1e-9);
      EXPECT_NEAR((r0.c_robot - r0.c_other).norm(), r0.core_distance, 1e-9);
      RowVector7 fd;
      for (int i = 0; i < kArmDofs; ++i) {
        Vector7 dq = Vector7::Zero();
        dq[i] = h;
        const double dp = f.at(q + dq, Vector7::Zero(), env, k).distance;
        const double dm = f.at(q - dq, Vector7::Zero(), env, k).distance;
        fd[i] = (dp - dm) / (2 * h);
      }
      EXPECT_LT((fd - r0.jacobian).cwiseAbs().maxCoeff(), 2e-6)
          << f.cm.pairLabel(k) << "\n fd " << fd << "\n J  " << r0.jacobian;
      ++tested[static_cast<int>(f.kindOf(k))];
    }
  }
  EXPECT_GT(tested[0], 50);
  EXPECT_GT(tested[1], 50);
  EXPECT_GT(tested[2], 50);
}

TEST(CollisionDistances, DistanceRateMatchesTimeDerivativeIncludingPersonMotion) {
  Fixture f;
  std::mt19937 rng(5);
  const double h = 1e-6;
  int tested = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const Vector7 q = randomConfiguration(f.m, rng), v = randomVelocity(rng);
    forwardKinematics(f.m, f.data, q, v);
    const Vector3 tcp = framePlacement(f.m, f.data, f.m.frameId("tcp")).translation();
    CollisionEnvironment env = personAt(tcp + Vector3(0.12, 0.0, 0.05), rng);
    const Vector3 w(0.3, -0.5, 0.8), lin(-0.4, 0.2, 0.1);  // person segments' twists
    env.hand_velocity << lin, w;
    env.forearm_velocity << lin, -w;
    env.upper_arm_velocity << -lin, w;
    // the person at time t: each frame moves with its own constant twist
    auto moved = [&](double t) {
      CollisionEnvironment e = env;
      auto step = [t](Isometry& X, const Vector6& tw) {
        X.translation() += t * tw.head<3>();
        X.linear() = Eigen::AngleAxisd(t * tw.tail<3>().norm(), tw.tail<3>().normalized()).toRotationMatrix() * X.linear();
      };
      step(e.hand, env.hand_velocity);
      step(e.forearm, env.forearm_velocity);
      step(e.upper_arm, env.upper_arm_velocity);
      return e;
    };
    updateCollisions(f.cm, f.cd, f.m, f.data, env);
    const std::vector<PairResult> base = f.cd.results;
    for (int k = 0; k < f.cm.numPairs(); ++k) {
      if (!f.smooth(base[k]) || f.kindOf(k) != Kind::kPerson) continue;
      const double dp = f.at(q + h * v, v, moved(h), k).distance;
      const double dm = f.at(q - h * v, v, moved(-h), k).distance;
      EXPECT_NEAR(base[k].d_dot, (dp - dm) / (2 * h), 2e-6) << f.cm.pairLabel(k);
      ++tested;
    }
  }
  EXPECT_GT(tested, 30);
}

// Capsule pairs (robot-robot and robot-person segments, the person at rest):
// the closest points slide along the segments they lie inside, and the drift
// is the true distance's: d(q(t)) for q(t) = q + t v + t^2/2 a has
// d_ddot = Jd a + drift, with the witness points recomputed at each t. (A
// drift taken with the witness frozen on each body fails this by up to
// 0.3 m/s^2 here, and by ten times that for a fast arm gliding along itself.)
TEST(CollisionDistances, DriftIsTheSecondDerivativeOfTheDistanceForCapsulePairs) {
  Fixture f;
  std::mt19937 rng(9);
  const double h = 1e-4;
  int tested[3] = {0, 0, 0};
  int sliding = 0;  // pairs with a witness inside a segment (the new terms at work)
  const double parallel = std::cos(10.0 * M_PI / 180.0);  // the slide rate is held near parallel
  for (int trial = 0; trial < 40; ++trial) {
    const Vector7 q = randomConfiguration(f.m, rng), v = randomVelocity(rng, 1.5), acc = randomVelocity(rng, 3.0);
    CollisionEnvironment env;
    const std::vector<PairResult> base = f.personNearTcp(q, v, Vector3(0.15, -0.05, 0.0), rng, env);
    for (int k = 0; k < f.cm.numPairs(); ++k) {
      const PairResult& r = base[k];
      const Kind kind = f.kindOf(k);
      if (!f.smooth(r) || kind == Kind::kTable) continue;
      const int ia = f.cm.pairs[k].robot_body, io = f.cm.pairs[k].other_body;
      if (f.cm.bodies[io].shape.kind == ShapeSpec::Kind::kBox) continue;  // face contacts: next tests
      // where each witness lies: inside its segment or at an end (the same at +-h, or skip)
      auto inside = [&](const CollisionData& cd, int idx, const Vector3& c) {
        const Isometry& X = cd.body_pose[idx];
        return std::abs(X.linear().col(2).dot(c - X.translation())) < 0.5 * cd.shapes.segmentLength(idx) - 1e-6;
      };
      const bool in1 = inside(f.cd, ia, r.c_robot), in2 = inside(f.cd, io, r.c_other);
      const Vector3 u1 = f.cd.body_pose[ia].linear().col(2), u2 = f.cd.body_pose[io].linear().col(2);
      if (in1 && in2 && std::abs(u1.dot(u2)) > parallel) continue;
      bool same = true;
      auto d = [&](double t) {
        const PairResult& rt = f.at(q + t * v + 0.5 * t * t * acc, v, env, k);
        same = same && inside(f.cd, ia, rt.c_robot) == in1 && inside(f.cd, io, rt.c_other) == in2;
        return rt.distance;
      };
      const double second = (d(h) - 2 * d(0) + d(-h)) / (h * h);
      if (!same) continue;
      EXPECT_NEAR(second, r.jacobian.dot(acc) + r.drift, 2e-3 * (1.0 + std::abs(second))) << f.cm.pairLabel(k);
      ++tested[static_cast<int>(kind)];
      if (in1 || in2) ++sliding;
    }
    f.at(q, v, env, 0);  // restore
  }
  EXPECT_GT(tested[1], 30);
  EXPECT_GT(tested[2], 30);
  EXPECT_GT(sliding, 30);
}

// Capsules against a box's edges and corners (the person's hand, at rest):
// an edge is a line the box's closest point slides along, so only motion
// across it turns the normal; a corner is a point. The drift is the true
// distance's second derivative as above. (Taking every edge and corner as a
// point counts a capsule gliding along an edge as curving away from it: a
// finger passing a box's edge at 0.45 m/s read 6-30 m/s^2 of that and went
// 1.6 cm into the object it was meant to keep 5 mm from.)
TEST(CollisionDistances, DriftIsTheSecondDerivativeOfTheDistanceAtABoxsEdgesAndCorners) {
  Fixture f;
  std::mt19937 rng(17);
  const double h = 1e-4;
  int edges = 0, corners = 0;
  // how many of the box-frame coordinates of the box's witness sit on the box's bound
  auto feature = [&](const CollisionData& cd, int io, const Vector3& c) {
    const Vector3 q = cd.body_pose[io].inverse(Eigen::Isometry) * c;
    const Vector3& size = f.cm.bodies[io].shape.size;
    int on = 0;
    for (int k = 0; k < 3; ++k) on += std::abs(std::abs(q[k]) - 0.5 * size[k]) < 1e-7 ? 1 : 0;
    return on;
  };
  for (int trial = 0; trial < 60; ++trial) {
    const Vector7 q = randomConfiguration(f.m, rng), v = randomVelocity(rng, 1.5), acc = randomVelocity(rng, 3.0);
    CollisionEnvironment env;
    const std::vector<PairResult> base = f.personNearTcp(q, v, Vector3(0.12, -0.04, 0.02), rng, env);
    for (int k = 0; k < f.cm.numPairs(); ++k) {
      const PairResult& r = base[k];
      const int io = f.cm.pairs[k].other_body;
      if (!f.smooth(r) || io != f.cm.human_hand) continue;
      const int on = feature(f.cd, io, r.c_other);
      if (on < 2) continue;  // faces: the table's test
      bool same = true;
      auto d = [&](double t) {
        const PairResult& rt = f.at(q + t * v + 0.5 * t * t * acc, v, env, k);
        same = same && feature(f.cd, io, rt.c_other) == on;
        return rt.distance;
      };
      const double second = (d(h) - 2 * d(0) + d(-h)) / (h * h);
      if (!same) continue;
      EXPECT_NEAR(second, r.jacobian.dot(acc) + r.drift, 2e-3 * (1.0 + std::abs(second)))
          << f.cm.pairLabel(k) << (on == 2 ? " (edge)" : " (corner)");
      ++(on == 2 ? edges : corners);
    }
    f.at(q, v, env, 0);  // restore
  }
  EXPECT_GT(edges, 30);
  EXPECT_GT(corners, 30);
}

// Robot capsule end above the table top: the true distance is a height, so
// d(q(t)) for q(t) = q + t v + t^2/2 a must have d_ddot = Jd a + drift, and
// drift = d/dt (Jd(q)) v with the witness points recomputed by FCL.
TEST(CollisionDistances, TableDriftIsExactSecondDerivative) {
  Fixture f;
  std::mt19937 rng(21);
  const double h = 1e-4;
  int tested = 0;
  const CollisionBody& table = f.cm.bodies[f.cm.table];
  for (int trial = 0; trial < 40; ++trial) {
    const Vector7 q = randomConfiguration(f.m, rng), v = randomVelocity(rng), acc = randomVelocity(rng, 3.0);
    forwardKinematics(f.m, f.data, q, v);
    updateCollisions(f.cm, f.cd, f.m, f.data, CollisionEnvironment{});
    const std::vector<PairResult> base = f.cd.results;
    for (int k = 0; k < f.cm.numPairs(); ++k) {
      const PairResult& r = base[k];
      if (f.kindOf(k) != Kind::kTable || !f.smooth(r)) continue;
      // witness strictly inside the top face, robot witness at a segment end
      const Vector3 local = table.local.inverse() * r.c_other;
      if (std::abs(local.x()) > 0.5 * table.shape.size.x() - 1e-3 ||
          std::abs(local.y()) > 0.5 * table.shape.size.y() - 1e-3 || local.z() < 0.5 * table.shape.size.z() - 1e-9)
        continue;
      EXPECT_NEAR(r.normal.z(), 1.0, 1e-9);
      const CollisionBody& a = f.cm.bodies[f.cm.pairs[k].robot_body];
      const Capsule& cap = f.m.capsules[a.capsule];
      const Vector3 ea = f.data.oMb[a.body] * cap.a, eb = f.data.oMb[a.body] * cap.b;
      if (std::min((r.c_robot - ea).norm(), (r.c_robot - eb).norm()) > 1e-9) continue;

      auto d = [&](double t) { return f.at(q + t * v + 0.5 * t * t * acc, v, CollisionEnvironment{}, k).distance; };
      const double second = (d(h) - 2 * d(0) + d(-h)) / (h * h);
      EXPECT_NEAR(second, r.jacobian.dot(acc) + r.drift, 1e-4 * (1.0 + std::abs(second))) << f.cm.pairLabel(k);

      const double hj = 1e-6;
      const double jp = f.at(q + hj * v, v, CollisionEnvironment{}, k).jacobian.dot(v);
      const double jm = f.at(q - hj * v, v, CollisionEnvironment{}, k).jacobian.dot(v);
      EXPECT_NEAR(r.drift, (jp - jm) / (2 * hj), 1e-5 * (1.0 + std::abs(r.drift))) << f.cm.pairLabel(k);
      ++tested;
    }
  }
  EXPECT_GT(tested, 20);
}

TEST(CollisionDistances, BroadPhaseOnlyDropsPairsBeyondReach) {
  const Model& m = pandaModel();
  CollisionConfig narrow_cfg = wideConfig();
  narrow_cfg.broadphase_margin = 0.05;
  for (auto& p : narrow_cfg.pairs) p.damper.i_dist = 0.05;
  const CollisionModel narrow = buildCollisionModel(m, narrow_cfg);
  const CollisionModel wide = buildCollisionModel(m, wideConfig());
  ASSERT_EQ(narrow.numPairs(), wide.numPairs());
  CollisionData cn(narrow), cw(wide);
  Data data(m);
  std::mt19937 rng(77);
  int culled = 0, kept = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const Vector7 q = randomConfiguration(m, rng);
    forwardKinematics(m, data, q, Vector7::Zero());
    const Vector3 tcp = framePlacement(m, data, m.frameId("tcp")).translation();
    const CollisionEnvironment env = personAt(tcp + Vector3(0.1, 0.0, 0.05), rng);
    updateCollisions(narrow, cn, m, data, env);
    updateCollisions(wide, cw, m, data, env);
    EXPECT_EQ(cn.num_narrow, cn.num_active);
    for (int k = 0; k < wide.numPairs(); ++k) {
      ASSERT_TRUE(cw.results[k].active);
      if (cn.results[k].active) {
        ++kept;
        EXPECT_NEAR(cn.results[k].distance, cw.results[k].distance, 1e-12);
      } else {
        ++culled;
        EXPECT_GT(cw.results[k].distance, 0.05 + 0.05) << wide.pairLabel(k);
      }
    }
  }
  EXPECT_GT(culled, kept);  // most pairs are far most of the time
  EXPECT_GT(kept, 0);
}

TEST(CollisionDistances, OverlappingCoresKeepAUsableRow) {
  Fixture f;
  forwardKinematics(f.m, f.data, readyPose(), Vector7::Zero());
  std::mt19937 rng(1);
  // first a separated person to learn the normal, then the forearm through the hand capsule
  const Vector3 tcp = framePlacement(f.m, f.data, f.m.frameId("tcp")).translation();
  CollisionEnvironment env = personAt(tcp + Vector3(0.2, 0.0, 0.0), rng);
  updateCollisions(f.cm, f.cd, f.m, f.data, env);
  env.forearm.translation() = tcp - env.forearm.linear() * Vector3(0, 0, 0.5 * env.forearm_length);
  updateCollisions(f.cm, f.cd, f.m, f.data, env);
  bool any = false;
  for (int k = 0; k < f.cm.numPairs(); ++k) {
    const PairResult& r = f.cd.results[k];
    if (!r.active || f.cm.bodies[f.cm.pairs[k].other_body].kind != CollisionBodyKind::kHumanForearm) continue;
    EXPECT_TRUE(std::isfinite(r.distance));
    EXPECT_TRUE(r.jacobian.allFinite());
    EXPECT_TRUE(std::isfinite(r.drift));
    EXPECT_NEAR(r.normal.norm(), 1.0, 1e-9);
    if (r.distance < 0.0) any = true;
  }
  EXPECT_TRUE(any);
}

// The object the person holds out is an obstacle while it is seen (and only then).
TEST(CollisionDistances, ObjectIsAnObstacleOnlyWhileItIsSeen) {
  const Model& m = pandaModel();
  CollisionConfig cfg = parseCollisionConfig(R"(
defaults: {iDist: 0.05, sDist: 0.005}
pairs:
  - {name: object_gripper, robot: [panda_hand*, panda_*finger], other: object}
)",
                                             "object.yaml");
  cfg.object.shape.kind = ShapeSpec::Kind::kBox;
  cfg.object.shape.size = Vector3(0.06, 0.06, 0.20);
  const CollisionModel cm = buildCollisionModel(m, cfg);
  ASSERT_GE(cm.object, 0);
  ASSERT_GT(cm.numPairs(), 0);
  CollisionData cd(cm);
  Data data(m);
  forwardKinematics(m, data, readyPose(), Vector7::Zero());
  const Isometry tcp = framePlacement(m, data, m.frameId("tcp"));
  // a bottle standing 4 cm below the fingertips' frame, centred under the gripper
  CollisionEnvironment env;
  env.object_valid = true;
  env.object.translation() = tcp.translation() - Vector3(0.0, 0.0, 0.10 + 0.04);
  updateCollisions(cm, cd, m, data, env);
  double nearest = 1e9;
  for (int k = 0; k < cm.numPairs(); ++k)
    if (cd.results[k].active) nearest = std::min(nearest, cd.results[k].distance);
  EXPECT_LT(nearest, 0.05);  // the fingertips are within reach of the damper
  EXPECT_GT(nearest, 0.0);
  // not seen (or held by the robot): no rows
  env.object_valid = false;
  updateCollisions(cm, cd, m, data, env);
  for (int k = 0; k < cm.numPairs(); ++k) EXPECT_FALSE(cd.results[k].active) << cm.pairLabel(k);
}

// The hand's way to the end of its reach: a capsule of the hand's size from
// the grip point now to the predicted rest, with rows only while a forecast
// is trusted and the person is seen.
TEST(CollisionDistances, TheHandForecastIsTheHandsWayToItsPredictedRest) {
  const Model& m = pandaModel();
  CollisionConfig cfg = parseCollisionConfig(R"(
defaults: {iDist: 0.05, sDist: 0.005}
person:
  hand: {size: [0.09, 0.08, 0.03]}
pairs:
  - {name: forecast, robot: [panda_hand*], other: human_hand_forecast, margin: 0.0}
)",
                                             "forecast.yaml");
  const CollisionModel cm = buildCollisionModel(m, cfg);
  ASSERT_GE(cm.human_hand_forecast, 0);
  EXPECT_DOUBLE_EQ(cm.bodies[cm.human_hand_forecast].radius, 0.045);
  CollisionData cd(cm);
  Data data(m);
  forwardKinematics(m, data, readyPose(), Vector7::Zero());
  const Vector3 tcp = framePlacement(m, data, m.frameId("tcp")).translation();
  auto nearest = [&](const CollisionEnvironment& env) {
    updateCollisions(cm, cd, m, data, env);
    double d = 1e9;
    for (int k = 0; k < cm.numPairs(); ++k)
      if (cd.results[k].active) d = std::min(d, cd.results[k].distance);
    return d;
  };
  // a hand 40 cm to the side of the gripper, its reach ending 40 cm to the other side:
  // the way passes 10 cm under the TCP
  CollisionEnvironment env;
  env.person_valid = true;
  env.hand.translation() = tcp + Vector3(0.0, 0.4, -0.10);
  env.hand_forecast.translation() = tcp + Vector3(0.0, -0.4, -0.10);
  EXPECT_EQ(nearest(env), 1e9) << "no forecast: no rows";
  env.hand_forecast_valid = true;
  // the fingertips' capsule (2 cm round a segment 3.4 mm above the TCP) against the way
  const double crossing = nearest(env);
  EXPECT_NEAR(crossing, 0.10 + 0.0034 - 0.02 - 0.045, 2e-3);
  // a way that ends 20 cm before it passes the gripper is farther
  env.hand_forecast.translation() = tcp + Vector3(0.0, 0.2, -0.10);
  EXPECT_GT(nearest(env), crossing + 0.04);
  env.person_valid = false;
  EXPECT_EQ(nearest(env), 1e9) << "the person unseen: no rows";
}
