// Collision avoidance in closed loop with the real controller
// (control::Controller + CollisionConstraint from config/collision.yaml):
//  1. self-collision: a pose target next to the base and a posture target that
//     folds joint 4 would fold the arm into itself; with the constraint every
//     self pair stays above its sDist (kinematic integration of the QP's qddot);
//  2. the table: in MuJoCo, a pose target 5 cm below the table top; with the
//     constraint the robot-table distance stays above sDist and MuJoCo reports
//     no robot-table contact.
// Each has a negative control: the same run without the collision constraint
// does get closer than sDist (so the positive runs mean something).
// Distances are judged twice: from the constraint's own data, and by an
// independent monitor (same pairs, own Data) that also runs when the
// constraint is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include <mujoco/mujoco.h>

#include "control/collision/collision_config.hpp"
#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_model.hpp"
#include "control/constraints/collision_constraint.hpp"
#include "control/controller.hpp"
#include "control/controller_config.hpp"
#include "control/model/algorithms.hpp"
#include "control/model/model.hpp"
#include "scenes/sim/simulation.hpp"

using namespace handover;
using namespace handover::control;

namespace {

enum class PairKind { kSelf, kTable };

bool pairIs(const CollisionModel& cm, int k, PairKind kind) {
  const CollisionBody& other = cm.bodies[cm.pairs[k].other_body];
  return kind == PairKind::kSelf ? other.isRobot() : other.kind == CollisionBodyKind::kTable;
}

/// Smallest (distance - sDist) and smallest distance over active pairs of `kind`.
struct Clearance {
  double margin_to_sdist = std::numeric_limits<double>::infinity();  ///< min (d - sDist), m
  double distance = std::numeric_limits<double>::infinity();         ///< min d, m
  int active = 0;
  std::string closest;  ///< pair label of the smallest d - sDist
};

Clearance clearance(const CollisionModel& cm, const CollisionData& cd, PairKind kind) {
  Clearance c;
  for (int k = 0; k < cm.numPairs(); ++k) {
    const PairResult& r = cd.results[k];
    if (!r.active || !pairIs(cm, k, kind)) continue;
    ++c.active;
    c.distance = std::min(c.distance, r.distance);
    const double m = r.distance - cm.pairs[k].damper.s_dist;
    if (m < c.margin_to_sdist) {
      c.margin_to_sdist = m;
      c.closest = cm.pairLabel(k);
    }
  }
  return c;
}

/// Independent judge: the same pairs as config/collision.yaml, its own Data,
/// no person. Works whether or not the controller has the constraint.
struct Monitor {
  const Model& model;
  CollisionModel cm;
  CollisionData cd;
  Data data;
  Clearance worst_self, worst_table;

  Monitor(const Model& m, const CollisionConfig& cfg) : model(m), cm(buildCollisionModel(m, cfg)), cd(cm), data(m) {}

  void observe(const Vector7& q, const Vector7& qd) {
    computeAll(model, data, q, qd);
    updateCollisions(cm, cd, model, data, CollisionEnvironment{});
    merge(worst_self, clearance(cm, cd, PairKind::kSelf));
    merge(worst_table, clearance(cm, cd, PairKind::kTable));
  }
  static void merge(Clearance& worst, const Clearance& now) {
    worst.active += now.active;
    worst.distance = std::min(worst.distance, now.distance);
    if (now.margin_to_sdist < worst.margin_to_sdist) {
      worst.margin_to_sdist = now.margin_to_sdist;
      worst.closest = now.closest;
    }
  }
};

const std::string kUrdf = std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf";

Isometry pointingDown(const Vector3& p) {
  Isometry X = Isometry::Identity();
  X.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();  // tcp z toward -z world
  X.translation() = p;
  return X;
}

/// A controller on the repository's model and config, with the set-point pose
/// task on instead of tracking (no observation target in these runs), and the
/// collision constraint from config/collision.yaml when `with_collision`.
/// These runs drive the controller below the handover cycle on purpose (its
/// state machine would replace the targets): docs/architecture.md.
struct Rig {
  ControllerConfig cfg = loadControllerConfig(defaultControllerConfigPath());
  CollisionConfig ccfg = loadCollisionConfig(defaultCollisionConfigPath());
  Controller controller;
  std::shared_ptr<CollisionConstraint> collision;

  // the collision constraint is config/controller.yaml's "collision" entry, built
  // by the registry as in the handover cycle (skipped without a collision scene)
  explicit Rig(bool with_collision)
      : controller(loadModel(kUrdf), cfg, ControllerRegistry::shipped(), with_collision ? &ccfg : nullptr) {
    for (const auto& c : controller.constraints())
      if (!collision) collision = std::dynamic_pointer_cast<CollisionConstraint>(c);
    EXPECT_EQ(collision != nullptr, with_collision);
    if (collision) collision->setEnvironment(CollisionEnvironment{});  // no person
  }
  void start(const Vector7& q0, const Isometry& pose_target, const Vector7& posture_target) {
    ControlInputs in;
    in.q = q0;
    controller.reset(in);
    EXPECT_TRUE(controller.setTaskEnabled("tracking", false));
    EXPECT_TRUE(controller.setTaskEnabled("pose", true));
    controller.setPoseTarget(pose_target);
    controller.setPostureTarget(posture_target);
  }
};

Vector7 readyPose() { return loadControllerConfig(defaultControllerConfigPath()).posture.target; }

// ---------------------------------------------------------------------------
// 1. Self-collision, kinematic integration of the controller's qddot at 1 ms.

struct SelfRun {
  Clearance monitor;       ///< independent judge
  Clearance constraint;    ///< from CollisionConstraint::collisionData() (with the constraint only)
  double final_tcp_error = 0.0;  ///< m, how close the TCP got to the (unreachable) target
  long fallbacks = 0;
};

SelfRun runSelf(bool with_collision, const Isometry& target, double seconds) {
  Rig rig(with_collision);
  const Vector7 q0 = readyPose();
  // posture: joint 4 folded fully (the pose task, far heavier, decides where the hand goes)
  Vector7 fold = q0;
  fold[3] = rig.controller.model().q_min[3];
  rig.start(q0, target, fold);
  Monitor monitor(rig.controller.model(), rig.ccfg);

  SelfRun out;
  const double dt = rig.cfg.period;
  Vector7 q = q0, qd = Vector7::Zero();
  ControlInputs in;
  const int steps = static_cast<int>(std::lround(seconds / dt));
  for (int k = 0; k <= steps; ++k) {
    monitor.observe(q, qd);
    if (k == steps) break;
    in.time = k * dt;
    in.q = q;
    in.qd = qd;
    rig.controller.step(in);
    if (rig.collision)
      Monitor::merge(out.constraint,
                     clearance(rig.collision->collisionModel(), rig.collision->collisionData(), PairKind::kSelf));
    qd += dt * rig.controller.lastQdd();  // semi-implicit Euler
    q += dt * qd;
  }
  out.monitor = monitor.worst_self;
  out.final_tcp_error = (rig.controller.tcpPose().translation() - target.translation()).norm();
  out.fallbacks = rig.controller.fallbackCount();
  return out;
}

Isometry pointingAlongMinusX(const Vector3& p) {
  Isometry X = Isometry::Identity();
  X.linear() = Eigen::AngleAxisd(-M_PI / 2, Vector3::UnitY()).toRotationMatrix();  // tcp z toward -x world
  X.translation() = p;
  return X;
}

TEST(CollisionClosedLoop, SelfCollisionKeptAboveSafetyDistance) {
  // TCP targets right next to links 0-2, with joint 4 folded fully: unconstrained,
  // the hand ends inside the base. (The TCP pointing down at (0.05, 0, 0.25) is
  // not enough: joint 4's limit holds the hand 1.5 cm above sDist there.)
  struct Case {
    const char* name;
    Isometry target;
  };
  const Case cases[] = {
      {"TCP at (0.05, 0, 0.30) aimed at the base (-x)", pointingAlongMinusX(Vector3(0.05, 0.0, 0.30))},
      {"TCP at (-0.05, 0.12, 0.30) pointing down, beside the base", pointingDown(Vector3(-0.05, 0.12, 0.30))},
  };
  const double seconds = 2.5;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const SelfRun on = runSelf(true, c.target, seconds);
    const SelfRun off = runSelf(false, c.target, seconds);
    std::printf("%s\n", c.name);
    std::printf("  with constraint:    min d - sDist = %+.5f m (min d %.4f m, %s), constraint data %+.5f m, "
                "TCP %.3f m from target, fallbacks %ld\n",
                on.monitor.margin_to_sdist, on.monitor.distance, on.monitor.closest.c_str(),
                on.constraint.margin_to_sdist, on.final_tcp_error, on.fallbacks);
    std::printf("  without constraint: min d - sDist = %+.5f m (min d %.4f m, %s), TCP %.3f m from target\n",
                off.monitor.margin_to_sdist, off.monitor.distance, off.monitor.closest.c_str(), off.final_tcp_error);

    // the pairs were really evaluated, by both the constraint and the monitor
    ASSERT_GT(on.constraint.active, 0);
    ASSERT_GT(on.monitor.active, 0);
    // negative control: the targets do fold the arm into itself
    EXPECT_LT(off.monitor.margin_to_sdist, -1e-3) << "the target no longer brings the arm below sDist: pick a nastier one";
    // with the constraint, every self pair stays at or above its sDist
    EXPECT_GE(on.constraint.margin_to_sdist, -1e-3) << on.constraint.closest;
    EXPECT_GE(on.monitor.margin_to_sdist, -1e-3) << on.monitor.closest;
    EXPECT_EQ(on.fallbacks, 0);
  }
}

// ---------------------------------------------------------------------------
// 2. The table, in MuJoCo with the controller's torques.

/// Contacts between robot geoms (contype 1, not the base link) and the table's
/// geoms ("table*"), read from MuJoCo's contact list (sim::ContactReport has
/// no robot-table count). Read-only use of the diagnostics accessors.
int robotTableContacts(const sim::Simulation& sim) {
  const mjModel* m = sim.mujocoModel();
  const mjData* d = sim.mujocoData();
  auto isTable = [&](int g) {
    const char* n = mj_id2name(m, mjOBJ_GEOM, g);
    return n && std::strncmp(n, "table", 5) == 0;
  };
  auto isRobot = [&](int g) {
    if (m->geom_contype[g] != 1) return false;
    const char* body = mj_id2name(m, mjOBJ_BODY, m->geom_bodyid[g]);
    return body && std::strncmp(body, "panda_", 6) == 0 && std::strcmp(body, "panda_link0") != 0;
  };
  int n = 0;
  for (int i = 0; i < d->ncon; ++i) {
    const int g1 = d->contact[i].geom1, g2 = d->contact[i].geom2;
    if ((isTable(g1) && isRobot(g2)) || (isTable(g2) && isRobot(g1))) ++n;
  }
  return n;
}

struct TableRun {
  Clearance monitor;
  Clearance constraint;
  int contact_steps = 0;  ///< steps with at least one robot-table contact in MuJoCo
  double min_tcp_z = std::numeric_limits<double>::infinity();  ///< m, ground truth (MuJoCo "tcp" site)
  long fallbacks = 0;
};

TableRun runTable(bool with_collision, double seconds) {
  Rig rig(with_collision);
  sim::Simulation sim;
  sim.load(sim::SimOptions{});
  const Vector7 q0 = readyPose();
  sim.reset(q0, 0.08);
  // 5 cm below the table top, in front of the robot, pointing down
  rig.start(q0, pointingDown(Vector3(0.45, 0.0, -0.05)), q0);
  Monitor monitor(rig.controller.model(), rig.ccfg);

  TableRun out;
  ControlInputs in;
  const int steps = static_cast<int>(std::lround(seconds / sim.timestep()));
  for (int k = 0; k < steps; ++k) {
    const sim::ArmState arm = sim.armState();
    monitor.observe(arm.q, arm.qd);
    in.time = arm.time;
    in.q = arm.q;
    in.qd = arm.qd;
    sim::ArmCommand cmd;
    cmd.tau = rig.controller.step(in);
    if (rig.collision)
      Monitor::merge(out.constraint,
                     clearance(rig.collision->collisionModel(), rig.collision->collisionData(), PairKind::kTable));
    sim.applyCommand(cmd);
    sim.step();
    // contacts() and tcpPose() describe the state this step started from
    if (robotTableContacts(sim) > 0) ++out.contact_steps;
    out.min_tcp_z = std::min(out.min_tcp_z, sim.tcpPose().translation().z());
  }
  monitor.observe(sim.armState().q, sim.armState().qd);
  out.monitor = monitor.worst_table;
  out.fallbacks = rig.controller.fallbackCount();
  return out;
}

TEST(CollisionClosedLoop, TableNeverTouchedInSimulation) {
  const double seconds = 2.0;
  const TableRun on = runTable(true, seconds);
  const TableRun off = runTable(false, seconds);
  std::printf("table, with constraint:    min d - sDist = %+.5f m (min d %.4f m, %s), constraint data %+.5f m, "
              "min TCP z %.4f m, contact steps %d, fallbacks %ld\n",
              on.monitor.margin_to_sdist, on.monitor.distance, on.monitor.closest.c_str(),
              on.constraint.margin_to_sdist, on.min_tcp_z, on.contact_steps, on.fallbacks);
  std::printf("table, without constraint: min d - sDist = %+.5f m (min d %.4f m, %s), min TCP z %.4f m, "
              "contact steps %d\n",
              off.monitor.margin_to_sdist, off.monitor.distance, off.monitor.closest.c_str(), off.min_tcp_z,
              off.contact_steps);

  ASSERT_GT(on.constraint.active, 0);
  ASSERT_GT(on.monitor.active, 0);
  // negative control: without the constraint the arm drives into the table
  // (MuJoCo's table stops it: contacts, and the distance falls below sDist)
  EXPECT_LT(off.monitor.margin_to_sdist, -1e-3);
  EXPECT_GT(off.contact_steps, 0);
  // with it: above sDist by the constraint's and the monitor's distances, no
  // contact in MuJoCo, TCP above the table top
  EXPECT_GE(on.constraint.margin_to_sdist, -1e-3) << on.constraint.closest;
  EXPECT_GE(on.monitor.margin_to_sdist, -1e-3) << on.monitor.closest;
  EXPECT_EQ(on.contact_steps, 0);
  EXPECT_GT(on.min_tcp_z, 0.0);
  EXPECT_EQ(on.fallbacks, 0);
}

}  // namespace
