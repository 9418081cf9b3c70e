// The resolved collision scene (const, built once from the robot Model and a
// CollisionConfig; allocates, start-up only).
//
// Bodies: one per robot capsule (Model::capsules, moved by its body), plus the
// table (static box, top face at z = 0) and the person's hand (box), forearm
// and upper arm (capsules), torso and legs (boxes), head (sphere) and the
// other arm hanging beside the torso (capsule). Each body is a "core" shape (segment or box) with
// a radius around it; distances are core distance minus radii minus margin.
// Pairs: every (robot capsule, other body) pair produced by the config's pair
// rules, with the rule's damper settings and margin. Adjacent and same-body
// robot capsules are never paired (the joint between them keeps them close).
#pragma once

#include <string>
#include <vector>

#include "control/collision/collision_config.hpp"
#include "control/collision/shape_distance.hpp"
#include "control/model/model.hpp"

namespace handover::control {

enum class CollisionBodyKind {
  kRobot, kTable, kHumanHand, kHumanForearm, kHumanUpperArm, kObject,
  kHumanTrunk,  ///< legs, torso, head or the hanging free arm: fixed shapes in the torso frame
  /// the way the person's reaching hand will go: a capsule of the hand's
  /// size from where it is to where the reach will end (its predicted rest):
  /// not the person, where the person is going
  kHumanHandForecast
};

struct CollisionBody {
  std::string name;                 ///< robot: capsule name; else "table", "human_hand", ...
  std::string link;                 ///< robot: URDF link; else same as name
  CapsuleRole role = CapsuleRole::kArm;  ///< robot: the capsule's role (robot description)
  CollisionBodyKind kind = CollisionBodyKind::kRobot;
  int capsule = -1;                 ///< robot: index into Model::capsules
  int body = -1;                    ///< robot: model body 0..7
  ShapeSpec shape;                  ///< core shape
  double radius = 0.0;              ///< m, swept around the core
  /// robot: core canonical frame in the body frame; table: world pose of the
  /// box centre; hand: box centre in the hand frame; arm segments: unused.
  Isometry local = Isometry::Identity();
  bool isRobot() const { return kind == CollisionBodyKind::kRobot; }
  bool isPerson() const {
    return kind == CollisionBodyKind::kHumanHand || kind == CollisionBodyKind::kHumanForearm ||
           kind == CollisionBodyKind::kHumanUpperArm || kind == CollisionBodyKind::kHumanTrunk;
  }
};

struct CollisionPair {
  int rule = 0;            ///< index into CollisionModel::rule_names
  int robot_body = 0;      ///< index into bodies (always a robot capsule)
  int other_body = 0;      ///< index into bodies (robot capsule, table or person)
  DamperSettings damper;
  /// m, extra clearance subtracted from the distance: the rule's margin, plus
  /// the sensing budget (CollisionConfig::sensing_error) for a person body
  double margin = 0.0;
};

struct CollisionModel {
  std::vector<CollisionBody> bodies;
  std::vector<CollisionPair> pairs;
  std::vector<std::string> rule_names;     ///< pair rules by name (run-time switches)
  std::vector<bool> rule_enabled;          ///< start-up state of each rule
  std::vector<RuleScope> rule_scope;       ///< when each rule is on (collision_config.hpp)
  double broadphase_margin = 0.15;         ///< m
  int table = -1, human_hand = -1, human_forearm = -1, human_upper_arm = -1, object = -1;  ///< body indices
  int human_torso = -1, human_legs = -1, human_head = -1;                                  ///< body indices (trunk)
  int human_hand_forecast = -1;                                                            ///< body index
  int human_free_arm = -1;  ///< body index: the other arm, hanging beside the torso (a trunk body)
  /// Model body (0..7) the gripper's capsules are on (the flange's: the hand
  /// is fixed to it); -1 without gripper capsules.
  int gripper_body = -1;

  /// Index of a rule, or -1.
  int ruleIndex(const std::string& name) const;
  int numPairs() const { return static_cast<int>(pairs.size()); }
  /// "<hand link>/hand_a - human_hand" style label of a pair (logs, messages).
  std::string pairLabel(int pair) const;
};

/// Resolves the config's pair rules against the model's capsules. Throws
/// InputError naming the config file, line and rule when a pattern matches
/// nothing, a rule yields no pair, a pair is listed twice, a table pair names
/// a link that rests on the table (link0, link1), or sizes are invalid.
CollisionModel buildCollisionModel(const Model& model, const CollisionConfig& config);

}  // namespace handover::control
