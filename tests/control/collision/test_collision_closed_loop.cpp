// Collision avoidance in closed loop with the real controller, run through
// the handover's own control cycle (runtime::HandoverCycle::step, with a
// one-state table: Hold {pose, posture}; CollisionConstraint from
// config/collision.yaml):
//  1. self-collision: a pose target next to the base and a posture target that
//     folds joint 4 would fold the arm into itself; with the constraint every
//     self pair stays above its sDist (kinematic integration of the QP's qddot);
//  2. the table: in MuJoCo, a pose target 5 cm below the table top; with the
//     constraint the robot-table distance stays above sDist and MuJoCo reports
//     no robot-table contact.
// Each has a negative control: the same run without the collision constraint
// (the controller config's collision entry left out) does get closer than
// sDist (so the positive runs mean something).
// Distances are judged twice: from the constraint's own data, and by an
// independent monitor (same pairs, own Data) that also runs when the
// constraint is absent.
#include <gtest/gtest.h>

#include <algorithm>
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
#include "control/model/robot_description.hpp"
#include "perception/pose_source.hpp"
#include "runtime/handover_cycle.hpp"
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

Isometry pointingDown(const Vector3& p) {
  Isometry X = Isometry::Identity();
  X.linear() = Eigen::AngleAxisd(M_PI, Vector3::UnitX()).toRotationMatrix();  // tcp z toward -z world
  X.translation() = p;
  return X;
}

/// No pose samples: these runs have no person.
class NoSamples : public perception::PoseSource {
 public:
  bool poll(double, perception::PoseSample&) override { return false; }
};

/// The Hold state's table: the pose task toward `pose`, the posture task toward `posture`.
YAML::Node holdTable(const Isometry& pose, const Vector7& posture) {
  const Vector3 ypr = pose.linear().eulerAngles(2, 1, 0);  // R = Rz Ry Rx, as fsm::readPose
  YAML::Node hold;
  hold["type"] = "Hold";
  hold["pose"]["pos"] = std::vector<double>{pose.translation().x(), pose.translation().y(), pose.translation().z()};
  hold["pose"]["rpy"] = std::vector<double>{ypr[2], ypr[1], ypr[0]};
  hold["posture"] = std::vector<double>(posture.data(), posture.data() + 7);
  YAML::Node doc;
  doc["machine"]["states"]["Hold"] = hold;
  doc["machine"]["initial"] = "Hold";
  return doc;
}

/// The handover cycle on the repository's config, with the Hold table: the
/// set-point pose task on instead of tracking (no person, no observation
/// target in these runs), and the collision constraint from
/// config/collision.yaml only when `with_collision` (docs/architecture.md).
struct Rig {
  runtime::CycleSettings cs = runtime::defaultCycleSettings();
  std::unique_ptr<runtime::HandoverCycle> cycle;
  NoSamples none;

  Rig(bool with_collision, const Vector7& q0, const Isometry& pose_target, const Vector7& posture_target) {
    if (!with_collision) {
      auto& c = cs.controller.constraints;
      c.erase(std::remove_if(c.begin(), c.end(), [](const ElementEntry& e) { return e.type == "collision"; }), c.end());
      cs.collision_required = false;  // the negative control
    }
    cs.fsm_config_path = "test_collision_closed_loop: Hold table";
    cs.fsm_config = std::make_shared<const YAML::Node>(holdTable(pose_target, posture_target));
    cycle = std::make_unique<runtime::HandoverCycle>(cs);
    EXPECT_EQ(cycle->hasCollision(), with_collision);
    io::ArmState arm0;
    arm0.q = q0;
    cycle->start(arm0, false);
  }
  const Controller& controller() const { return cycle->controller(); }
  const CollisionConstraint* collision() const { return cycle->hasCollision() ? &cycle->collision() : nullptr; }
  const Vector7& step(double t, const Vector7& q, const Vector7& qd) {
    io::ArmState arm;
    arm.time = t;
    arm.q = q;
    arm.qd = qd;
    return cycle->step(t, arm, none).tau;
  }
};

Vector7 readyPose() { return loadControllerConfig(defaultControllerConfigPath()).posture.target; }
double joint4Min() { return loadModel(defaultRobotDescription(), 0.08).q_min[3]; }

// ---------------------------------------------------------------------------
// 1. Self-collision, kinematic integration of the controller's qddot at 1 ms.

struct SelfRun {
  Clearance monitor;       ///< independent judge
  Clearance constraint;    ///< from CollisionConstraint::collisionData() (with the constraint only)
  double final_tcp_error = 0.0;  ///< m, how close the TCP got to the (unreachable) target
  long fallbacks = 0;
};

SelfRun runSelf(bool with_collision, const Isometry& target, double seconds) {
  const Vector7 q0 = readyPose();
  // posture: joint 4 folded fully (the pose task, far heavier, decides where the hand goes)
  Vector7 fold = q0;
  fold[3] = joint4Min();
  Rig rig(with_collision, q0, target, fold);
  Monitor monitor(rig.controller().model(), rig.cs.collision);

  SelfRun out;
  const double dt = rig.cs.controller.period;
  Vector7 q = q0, qd = Vector7::Zero();
  const int steps = static_cast<int>(std::lround(seconds / dt));
  for (int k = 0; k <= steps; ++k) {
    monitor.observe(q, qd);
    if (k == steps) break;
    rig.step(k * dt, q, qd);
    if (const CollisionConstraint* c = rig.collision())
      Monitor::merge(out.constraint, clearance(c->collisionModel(), c->collisionData(), PairKind::kSelf));
    qd += dt * rig.controller().lastQdd();  // semi-implicit Euler
    q += dt * qd;
  }
  out.monitor = monitor.worst_self;
  out.final_tcp_error = (rig.controller().tcpPose().translation() - target.translation()).norm();
  out.fallbacks = rig.controller().fallbackCount();
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

/// Contacts between robot geoms (contype 1, below the base link of the robot
/// description) and the table's geoms ("table*"), read from MuJoCo's contact
/// list (sim::ContactReport has no robot-table count). Read-only use of the
/// diagnostics accessors.
int robotTableContacts(const sim::Simulation& sim) {
  const mjModel* m = sim.mujocoModel();
  const mjData* d = sim.mujocoData();
  static const std::string base_link = defaultRobotDescription().base_link;
  const int base = mj_name2id(m, mjOBJ_BODY, base_link.c_str());
  EXPECT_GE(base, 0) << base_link;
  auto isTable = [&](int g) {
    const char* n = mj_id2name(m, mjOBJ_GEOM, g);
    return n && std::strncmp(n, "table", 5) == 0;
  };
  auto isRobot = [&](int g) {
    if (m->geom_contype[g] != 1) return false;
    const int b = m->geom_bodyid[g];
    return b != base && b != 0 && m->body_rootid[b] == m->body_rootid[base];
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
  const Vector7 q0 = readyPose();
  // 5 cm below the table top, in front of the robot, pointing down
  Rig rig(with_collision, q0, pointingDown(Vector3(0.45, 0.0, -0.05)), q0);
  sim::Simulation sim;
  sim.load(sim::SimOptions{});
  sim.reset(q0, 0.08);
  Monitor monitor(rig.controller().model(), rig.cs.collision);

  TableRun out;
  const int steps = static_cast<int>(std::lround(seconds / sim.timestep()));
  for (int k = 0; k < steps; ++k) {
    const io::ArmState arm = sim.state();
    monitor.observe(arm.q, arm.qd);
    const io::ArmCommand& cmd = rig.cycle->step(arm.time, arm, rig.none);
    if (const CollisionConstraint* c = rig.collision())
      Monitor::merge(out.constraint, clearance(c->collisionModel(), c->collisionData(), PairKind::kTable));
    sim.apply(cmd);
    sim.step();
    // contacts() and tcpPose() describe the state this step started from
    if (robotTableContacts(sim) > 0) ++out.contact_steps;
    out.min_tcp_z = std::min(out.min_tcp_z, sim.tcpPose().translation().z());
  }
  monitor.observe(sim.state().q, sim.state().qd);
  out.monitor = monitor.worst_table;
  out.fallbacks = rig.controller().fallbackCount();
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
