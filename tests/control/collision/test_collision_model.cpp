// Pair rules resolved against the Panda's capsules.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "collision_test_util.hpp"
#include "config/input_error.hpp"
#include "control/collision/collision_distances.hpp"
#include "control/collision/collision_model.hpp"

using namespace handover;
using namespace handover::control;
using namespace handover::control::testing;

namespace {

std::string buildError(const std::string& pairs_yaml) {
  try {
    buildCollisionModel(pandaModel(), parseCollisionConfig(pairs_yaml, "rules.yaml"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CollisionModel, RepositoryConfigResolves) {
  const Model& m = pandaModel();
  const CollisionConfig cfg = loadCollisionConfig(defaultCollisionConfigPath());
  const CollisionModel cm = buildCollisionModel(m, cfg);
  ASSERT_EQ(cm.rule_names.size(), cfg.pairs.size());
  std::vector<int> per_rule(cfg.pairs.size(), 0);
  // a pair is listed once among the rules that can be on together: an
  // `apart` and a `sharing` rule never are (collision_config.hpp RuleScope)
  std::set<std::tuple<int, int, bool>> unique;
  for (const auto& p : cm.pairs) {
    ++per_rule[p.rule];
    const CollisionBody& a = cm.bodies[p.robot_body];
    const CollisionBody& o = cm.bodies[p.other_body];
    EXPECT_TRUE(a.isRobot());
    if (o.isRobot()) {
      EXPECT_GE(std::abs(a.body - o.body), 2) << cm.pairLabel(static_cast<int>(&p - cm.pairs.data()));
    }
    if (o.kind == CollisionBodyKind::kTable) {
      EXPECT_GE(a.body, 2);
    }
    const bool sharing = whileSharing(cm.rule_scope[p.rule]);
    EXPECT_TRUE(
        unique.insert({std::min(p.robot_body, p.other_body), std::max(p.robot_body, p.other_body), sharing}).second);
  }
  for (std::size_t r = 0; r < per_rule.size(); ++r) EXPECT_GT(per_rule[r], 0) << cm.rule_names[r];
  // the gripper-hand rule holds exactly the gripper capsules against the hand
  const int g = cm.ruleIndex("person_hand_gripper");
  ASSERT_GE(g, 0);
  for (const auto& p : cm.pairs) {
    if (p.rule != g) continue;
    EXPECT_EQ(cm.bodies[p.robot_body].link, "panda_hand");
    EXPECT_EQ(cm.bodies[p.other_body].kind, CollisionBodyKind::kHumanHand);
  }
}

TEST(CollisionModel, WildcardMatchesEveryCapsuleOfALink) {
  const CollisionModel cm = buildCollisionModel(
      pandaModel(), parseCollisionConfig("pairs: [{name: t, robot: panda_link5*, other: table}]", "t.yaml"));
  int link5 = 0;
  for (const auto& c : pandaModel().capsules) link5 += c.link == "panda_link5";
  EXPECT_EQ(cm.numPairs(), link5);
  EXPECT_GE(link5, 1);
}

// a rule names the robot description's link groups (config/robot.yaml
// link_groups), which expand to their links as if the rule listed them
TEST(CollisionModel, RobotDescriptionLinkGroupsExpandInRules) {
  const Model& m = pandaModel();
  ASSERT_FALSE(m.link_groups.empty());
  for (const LinkGroup& g : m.link_groups) {
    std::string patterns;
    for (const std::string& p : g.patterns) patterns += (patterns.empty() ? "" : ", ") + p;
    const CollisionModel by_group = buildCollisionModel(
        m, parseCollisionConfig("pairs: [{name: t, robot: " + g.name + ", other: human_hand}]", "t.yaml"));
    const CollisionModel by_links = buildCollisionModel(
        m, parseCollisionConfig("pairs: [{name: t, robot: [" + patterns + "], other: human_hand}]", "t.yaml"));
    ASSERT_EQ(by_group.numPairs(), by_links.numPairs()) << g.name;
    EXPECT_GT(by_group.numPairs(), 0) << g.name;
    for (int i = 0; i < by_group.numPairs(); ++i) EXPECT_EQ(by_group.pairLabel(i), by_links.pairLabel(i)) << g.name;
  }
  // a group of collision.yaml and a name that is neither still fail as before
  EXPECT_NE(buildError("pairs: [{name: t, robot: no_such_group, other: table}]").find("no_such_group"), std::string::npos);
}

TEST(CollisionModel, ReadyPoseRespectsItsOwnSafetyDistances) {
  const Model& m = pandaModel();
  const CollisionModel cm = buildCollisionModel(m, loadCollisionConfig(defaultCollisionConfigPath()));
  CollisionData cd(cm);
  Data data(m);
  forwardKinematics(m, data, readyPose(), Vector7::Zero());
  updateCollisions(cm, cd, m, data, CollisionEnvironment{});
  for (int k = 0; k < cm.numPairs(); ++k) {
    if (cd.results[k].active) {
      EXPECT_GT(cd.results[k].distance, cm.pairs[k].damper.i_dist) << cm.pairLabel(k);
    }
  }
}

TEST(CollisionModel, BadRulesAreInputErrors) {
  std::string e = buildError("pairs:\n  - {name: a, robot: panda_link9, other: table}\n");
  EXPECT_NE(e.find("rules.yaml:2"), std::string::npos) << e;
  EXPECT_NE(e.find("panda_link9"), std::string::npos) << e;

  e = buildError("pairs:\n  - {name: a, robot: table, other: panda_hand}\n");
  EXPECT_NE(e.find("not a robot link"), std::string::npos) << e;

  e = buildError("pairs:\n  - {name: a, robot: panda_hand, other: human_foot}\n");
  EXPECT_NE(e.find("human_foot"), std::string::npos) << e;

  e = buildError("pairs:\n  - {name: a, robot: panda_link1, other: table}\n");
  EXPECT_NE(e.find("rests on the table"), std::string::npos) << e;

  e = buildError("pairs:\n  - {name: a, robot: panda_link3, other: panda_link4}\n");
  EXPECT_NE(e.find("yields no collision pair"), std::string::npos) << e;

  e = buildError(
      "pairs:\n  - {name: a, robot: panda_hand, other: table}\n  - {name: b, robot: panda_hand*, other: table}\n");
  EXPECT_NE(e.find("already listed by rule 'a'"), std::string::npos) << e;
  EXPECT_NE(e.find("rules.yaml:3"), std::string::npos) << e;

  // a wildcard may match nothing as long as the rule yields pairs
  EXPECT_EQ(buildError("pairs: [{name: a, robot: [panda_hand, panda_*finger], other: table}]"), "");
}

TEST(CollisionModel, RulesSwitchByName) {
  const Model& m = pandaModel();
  const CollisionModel cm = buildCollisionModel(m, wideConfig());
  CollisionData cd(cm);
  Data data(m);
  forwardKinematics(m, data, readyPose(), Vector7::Zero());
  std::mt19937 rng(3);
  const CollisionEnvironment env = personAt(Vector3(0.5, 0.0, 0.4), rng);
  const int person = cm.ruleIndex("person");
  auto activeOf = [&](int rule) {
    int n = 0;
    for (int k = 0; k < cm.numPairs(); ++k) n += cd.results[k].active && cm.pairs[k].rule == rule;
    return n;
  };
  updateCollisions(cm, cd, m, data, env);
  EXPECT_GT(activeOf(person), 0);
  setRuleEnabled(cm, cd, "person", false);
  updateCollisions(cm, cd, m, data, env);
  EXPECT_EQ(activeOf(person), 0);
  EXPECT_GT(activeOf(cm.ruleIndex("table")), 0);
  setRuleEnabled(cm, cd, "person", true);
  updateCollisions(cm, cd, m, data, env);
  EXPECT_GT(activeOf(person), 0);
  try {
    setRuleEnabled(cm, cd, "persn", false);
    FAIL() << "unknown rule accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("persn"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("person"), std::string::npos);  // lists the known ones
  }
  // no valid person estimate: no person pair
  CollisionEnvironment gone = env;
  gone.person_valid = false;
  updateCollisions(cm, cd, m, data, gone);
  EXPECT_EQ(activeOf(person), 0);
}
