// Strict loading of collision configs: groups, wildcards, defaults, errors.
#include <gtest/gtest.h>

#include "config/input_error.hpp"
#include "control/collision/collision_config.hpp"

using namespace handover;
using namespace handover::control;

namespace {

std::string errorOf(const std::string& text) {
  try {
    parseCollisionConfig(text, "bad.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(GlobMatch, WildcardsAndLiterals) {
  EXPECT_TRUE(globMatch("panda_link5*", "panda_link5"));
  EXPECT_TRUE(globMatch("panda_link5*", "panda_link5_b"));
  EXPECT_FALSE(globMatch("panda_link5*", "panda_link4"));
  EXPECT_TRUE(globMatch("panda_*finger", "panda_leftfinger"));
  EXPECT_FALSE(globMatch("panda_*finger", "panda_leftfinger_tip"));
  EXPECT_TRUE(globMatch("human_?and", "human_hand"));
  EXPECT_TRUE(globMatch("*", "anything"));
  EXPECT_FALSE(globMatch("panda_hand", "panda_hand_a"));
  EXPECT_TRUE(globMatch("a*b*c", "a__b__c"));
  EXPECT_FALSE(globMatch("a*b*c", "a__c__b"));
}

TEST(CollisionConfig, GroupsExpandAndDefaultsApply) {
  const CollisionConfig c = parseCollisionConfig(R"(
defaults: {iDist: 0.06, sDist: 0.02}
person: {margin: 0.04}
groups:
  arm: [panda_link3, panda_link5*]
  person: [human_hand, human_forearm]
pairs:
  - {name: a, robot: arm, other: [table, panda_link0]}
  - {name: b, robot: [arm, panda_hand*], other: person, damping: 0.5, margin: 0.01}
  - {name: c, robot: panda_hand, other: human_forearm, enabled: false}
)", "t.yaml");
  ASSERT_EQ(c.pairs.size(), 3u);
  EXPECT_EQ(c.pairs[0].robot, (std::vector<std::string>{"panda_link3", "panda_link5*"}));
  EXPECT_EQ(c.pairs[0].other, (std::vector<std::string>{"table", "panda_link0"}));
  EXPECT_DOUBLE_EQ(c.pairs[0].damper.i_dist, 0.06);
  EXPECT_DOUBLE_EQ(c.pairs[0].damper.s_dist, 0.02);
  EXPECT_TRUE(c.pairs[0].damper.automatic);
  EXPECT_DOUBLE_EQ(c.pairs[0].margin, 0.0);  // not a person pair
  EXPECT_EQ(c.pairs[1].robot, (std::vector<std::string>{"panda_link3", "panda_link5*", "panda_hand*"}));
  EXPECT_EQ(c.pairs[1].other, (std::vector<std::string>{"human_hand", "human_forearm"}));
  EXPECT_FALSE(c.pairs[1].damper.automatic);
  EXPECT_DOUBLE_EQ(c.pairs[1].damper.damping, 0.5);
  EXPECT_DOUBLE_EQ(c.pairs[1].margin, 0.01);
  EXPECT_DOUBLE_EQ(c.pairs[2].margin, 0.04);  // person default
  EXPECT_FALSE(c.pairs[2].enabled);
  EXPECT_GT(c.pairs[2].line, c.pairs[1].line);
}

TEST(CollisionConfig, WhenTiesARuleToSharingTheObject) {
  const CollisionConfig c = parseCollisionConfig(R"(
pairs:
  - {name: a, robot: panda_hand, other: human_forearm}
  - {name: b, robot: panda_hand, other: human_upper_arm, when: apart}
  - {name: c, robot: panda_hand, other: human_upper_arm, when: sharing, margin: 0.0}
)", "t.yaml");
  ASSERT_EQ(c.pairs.size(), 3u);
  EXPECT_EQ(c.pairs[0].scope, RuleScope::kAlways);
  EXPECT_EQ(c.pairs[1].scope, RuleScope::kApart);
  EXPECT_TRUE(c.pairs[1].enabled);
  EXPECT_EQ(c.pairs[2].scope, RuleScope::kSharing);
  EXPECT_FALSE(c.pairs[2].enabled);  // nothing is shared at start-up
  std::string e = errorOf("pairs:\n  - {name: a, robot: panda_hand, other: table, when: sometimes}\n");
  EXPECT_NE(e.find("'sometimes' is not one of: always | apart | sharing | taking"), std::string::npos) << e;
  EXPECT_NE(e.find("bad.yaml:2"), std::string::npos) << e;
  e = errorOf("pairs:\n  - {name: a, robot: panda_hand, other: table, when: apart, enabled: false}\n");
  EXPECT_NE(e.find("not both"), std::string::npos) << e;
}

TEST(CollisionConfig, BuiltInDefaultsMatchTheIssue) {
  const CollisionConfig c = parseCollisionConfig("pairs: [{name: t, robot: panda_hand, other: table}]", "t.yaml");
  EXPECT_DOUBLE_EQ(c.pairs[0].damper.i_dist, 0.05);
  EXPECT_DOUBLE_EQ(c.pairs[0].damper.s_dist, 0.01);
  EXPECT_TRUE(c.pairs[0].damper.automatic);
}

TEST(CollisionConfig, UnseenHoldIsReadAndOffByDefault) {
  EXPECT_EQ(parseCollisionConfig("pairs: [{name: t, robot: panda_hand, other: table}]", "t.yaml").person.unseen_hold,
            0.0);
  const CollisionConfig c =
      parseCollisionConfig("person: {unseen_hold: 0.4}\npairs: [{name: t, robot: panda_hand, other: table}]", "t.yaml");
  EXPECT_DOUBLE_EQ(c.person.unseen_hold, 0.4);
}

TEST(CollisionConfig, RepositoryFileLoads) {
  const CollisionConfig c = loadCollisionConfig(defaultCollisionConfigPath());
  EXPECT_FALSE(c.pairs.empty());
  bool has_gripper_rule = false;
  for (const auto& p : c.pairs) {
    if (p.name == "person_hand_gripper") {
      has_gripper_rule = true;
      EXPECT_LT(p.margin, c.person.margin);
    }
  }
  EXPECT_TRUE(has_gripper_rule);
}

TEST(CollisionConfig, ErrorsNameFileKeyAndLine) {
  std::string e = errorOf("pairs:\n  - {name: a, robot: panda_hand, other: table, iDsit: 0.1}\n");
  EXPECT_NE(e.find("bad.yaml:2"), std::string::npos) << e;
  EXPECT_NE(e.find("iDsit"), std::string::npos) << e;

  e = errorOf("pairs:\n  - {name: a, robot: panda_hand, other: table, iDist: 0.01, sDist: 0.02}\n");
  EXPECT_NE(e.find("sDist"), std::string::npos) << e;
  EXPECT_NE(e.find("bad.yaml:2"), std::string::npos) << e;

  e = errorOf("pairs:\n  - {name: a, robot: panda_hand, other: table, damping: fast}\n");
  EXPECT_NE(e.find("pairs[0].damping"), std::string::npos) << e;
  EXPECT_NE(e.find("fast"), std::string::npos) << e;

  e = errorOf("pairs:\n  - {name: a, robot: panda_hand, other: table, damping: -1}\n");
  EXPECT_NE(e.find("damping"), std::string::npos) << e;

  e = errorOf("pairs:\n  - {name: a, robot: panda_hand, other: table}\n  - {name: a, robot: panda_link3, other: table}\n");
  EXPECT_NE(e.find("duplicate pair name 'a'"), std::string::npos) << e;
  EXPECT_NE(e.find("bad.yaml:3"), std::string::npos) << e;

  e = errorOf("pairs:\n  - {name: a, other: table}\n");
  EXPECT_NE(e.find("robot"), std::string::npos) << e;

  e = errorOf("person: {margin: -0.1}\npairs: [{name: a, robot: panda_hand, other: table}]\n");
  EXPECT_NE(e.find("person.margin"), std::string::npos) << e;

  e = errorOf("person: {unseen_hold: -1}\npairs: [{name: a, robot: panda_hand, other: table}]\n");
  EXPECT_NE(e.find("person.unseen_hold"), std::string::npos) << e;

  e = errorOf("table: {size: [1, 0, 1]}\npairs: [{name: a, robot: panda_hand, other: table}]\n");
  EXPECT_NE(e.find("table.size"), std::string::npos) << e;

  e = errorOf("pairs: []\n");
  EXPECT_NE(e.find("pairs"), std::string::npos) << e;

  e = errorOf("colision_pairs: 1\npairs: [{name: a, robot: panda_hand, other: table}]\n");
  EXPECT_NE(e.find("colision_pairs"), std::string::npos) << e;
  EXPECT_NE(e.find("bad.yaml:1"), std::string::npos) << e;

  EXPECT_NE(errorOf("pairs: [{name: a, robot: panda_hand, other: table\n").find("bad.yaml"), std::string::npos);
}
