// Collision settings read from config/collision.yaml (strict: every key is
// checked; errors name file, dotted key and line). Start-up only, not
// real-time safe.
//
// Bodies a pair rule can name:
//   robot capsules, matched by their URDF link (e.g. "<prefix>link5") or
//   capsule name; "*" and "?" are wildcards ("*link5*", "*finger");
//   "table" (a box whose top is the plane z = 0);
//   "human_hand" (a box in the hand frame), "human_forearm",
//   "human_upper_arm" (capsules along the segment's z axis), "human_torso",
//   "human_legs" (boxes in the torso frame), "human_head" (a sphere),
//   "human_free_arm" (the other arm hanging beside the torso: a capsule in
//   the torso frame).
// A list item that is the name of a group expands to that group's patterns.
// Units: m, m/s.
#pragma once

#include <string>
#include <vector>

#include "control/collision/shape_distance.hpp"
#include "control/types.hpp"

namespace handover::control {

/// Damping of the velocity damper. Automatic (mc_rtc): on entering iDist
/// with d_dot < 0, xi = -d_dot (iDist - sDist) / (d - sDist) + offset.
struct DamperSettings {
  double i_dist = 0.05;           ///< m, interaction distance: the damper acts below it
  double s_dist = 0.01;           ///< m, safety distance: d never goes below it
  bool automatic = true;          ///< automatic damping (default)
  double damping = 0.0;           ///< m/s, fixed xi when !automatic
  double damping_offset = 0.1;    ///< m/s, added to the automatic xi
};

/// One rule of the `pairs:` list: every robot capsule matched by `robot`
/// against every body matched by `other`. All the capsule pairs it yields
/// share its name (switched on and off together at run time).
/// When a pair rule is on: always (unless switched at run time by name), only
/// while the gripper and the person do not share the object (`apart`), or
/// only while they do (`sharing`: the fingers close on, hold or present the
/// object in the person's hand), or only while they do and the person still
/// carries it (`taking`: the robot's fingers close on the object in the
/// person's hand; not while the robot carries it and a receiver's hand
/// closes on it; nor once they hold it: the state machine's
/// fingers-around-object switch). The controller adapter switches the last
/// three with the state machine's hand-clearance and fingers-around-object
/// switches and the payload.
enum class RuleScope { kAlways, kApart, kSharing, kTaking };

/// A rule on only while the gripper shares the object with the person's hand
/// (`sharing` or `taking`): off at start-up, never on with an `apart` rule,
/// no sensing budget (robot and hand meet at the object by design).
inline bool whileSharing(RuleScope s) { return s == RuleScope::kSharing || s == RuleScope::kTaking; }

struct PairRule {
  std::string name;
  std::vector<std::string> robot;   ///< patterns / group names (already expanded)
  std::vector<std::string> other;   ///< patterns / group names (already expanded)
  DamperSettings damper;
  double margin = 0.0;              ///< m, extra clearance around the other body
  bool enabled = true;              ///< state at start-up (a `sharing` or `taking` rule starts off)
  RuleScope scope = RuleScope::kAlways;  ///< `when:` always | apart | sharing | taking
  int line = 0;                     ///< line in the file, for messages
};

struct TableSettings {
  Vector3 size = Vector3(1.2, 1.6, 0.05);   ///< full edges, m; top face at z = 0
  Vector3 center_xy = Vector3(0.3, 0.0, 0.0);  ///< x, y of the box centre, m (z unused)
};

/// The person's trunk in the torso frame (origin on the floor under the body
/// centre, x forward, z up). Not read from collision.yaml: the runtime sizes
/// it from the scenario's stature, as the simulated scene does
/// (the scenario body dimensions, app/validate/person_trunk.hpp). Defaults: a 1.75 m person.
struct PersonTrunk {
  Vector3 torso_size = Vector3(0.22, 0.38, 0.49);  ///< full edges, m
  double torso_centre = 1.1725;                     ///< box centre above the floor, m
  Vector3 legs_size = Vector3(0.18, 0.32, 0.9275);  ///< full edges, m
  double legs_centre = 0.46375;                     ///< m
  double head_radius = 0.105;                       ///< m
  double head_centre = 1.6275;                      ///< m
  /// The other arm (not handing, not tracked), hanging beside the torso: the
  /// core segment of one capsule from the shoulder to the fingertips (its
  /// radius: PersonSettings::free_arm_radius). Defaults: a 1.75 m person
  /// handing with the right hand (the free arm on the left, +y).
  Vector3 free_arm_top = Vector3(0.0, 0.235, 1.4315);
  Vector3 free_arm_bottom = Vector3(0.0, 0.235, 0.63525);
};

struct PersonSettings {
  Vector3 hand_size = Vector3(0.10, 0.09, 0.05);  ///< full edges of the hand box, m
  Isometry hand_offset = Isometry::Identity();     ///< box centre in the hand (grip point) frame
  double forearm_radius = 0.045;    ///< m
  double upper_arm_radius = 0.055;  ///< m
  /// m, the other (hanging, untracked) arm's capsule: one radius for upper
  /// arm, forearm and hand, so at least the upper arm's
  double free_arm_radius = 0.045;
  double margin = 0.03;             ///< m, default extra clearance for sensor noise
  /// s: a tracker gone silent leaves the person in the scene this long, at the
  /// estimator's last (predicted, then held) pose; 0 drops them at once
  double unseen_hold = 0.0;
  PersonTrunk trunk;                ///< legs, torso, head (set by the runtime)
};

/// The object the person holds out, as an obstacle while the gripper
/// approaches it (pair rules name it "object"). Not read from collision.yaml:
/// the runtime sets it from the object's geometry (scenario). Object frame
/// at the shape's centre.
struct ObjectShapeSettings {
  ShapeSpec shape = ShapeSpec{};   ///< core: a box, or a segment along z (length 0: a sphere)
  double radius = 0.03;            ///< m, swept around a segment core (0 for a box)
};

/// The pose sensor's error that every pair with the person budgets for
/// (collision.yaml `sensing_error`, docs/collision.md "Sensing budget"): a
/// tracker off by at most this much still leaves the pair's sDist to the true
/// person. m, s, m/s.
struct SensingError {
  double calibration = 0.0;   ///< m, constant offset of the tracked poses (extrinsic calibration)
  double noise = 0.0;         ///< m, standard deviation of one position sample
  double noise_sigmas = 3.0;  ///< standard deviations of noise the budget covers
  double latency = 0.0;       ///< s, delay of the poses the controller acts on
  double person_speed = 0.0;  ///< m/s, the person's speed near the robot during that delay
  /// m, the clearance added to the margin of every robot-person pair
  double budget() const { return calibration + noise_sigmas * noise + latency * person_speed; }
};

struct CollisionConfig {
  std::string file;                 ///< where it was read from (messages)
  double broadphase_margin = 0.15;  ///< m, pairs farther than iDist + this are skipped
  /// m/s^2, most acceleration away from a body a damper row may demand (and
  /// never more than half of what the row's Jacobian can reach at the joint
  /// acceleration limits): a person moving in faster than the robot can give
  /// way would otherwise make the QP infeasible (the robot then yields at
  /// this rate, and the state machine's safety stop takes over)
  double max_escape_acceleration = 8.0;
  /// fraction of a row's reach (|Jd| . a_max) it may demand (see above)
  double escape_reach_fraction = 0.5;
  DamperSettings defaults;
  TableSettings table;
  PersonSettings person;
  SensingError sensing_error;       ///< added to every robot-person pair's margin
  ObjectShapeSettings object;
  std::vector<PairRule> pairs;
};

/// Reads a collision config file. Throws InputError naming file/key/line.
CollisionConfig loadCollisionConfig(const std::string& path);
/// Same from YAML text; `origin` names the source in messages.
CollisionConfig parseCollisionConfig(const std::string& text, const std::string& origin);
/// The repository's config/collision.yaml.
std::string defaultCollisionConfigPath();

/// Glob match with '*' (any run) and '?' (one character).
bool globMatch(const std::string& pattern, const std::string& name);

}  // namespace handover::control
