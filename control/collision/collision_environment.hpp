// What the collision scene needs to know each cycle about the world outside
// the robot: the person's arm segments as world poses (from perception).
// A plain fixed-size struct: copying it is real-time safe.
#pragma once

#include "control/types.hpp"

namespace handover::control {

struct CollisionEnvironment {
  /// false: no trustworthy person estimate; pairs with the person give no rows.
  bool person_valid = false;
  Isometry hand = Isometry::Identity();       ///< grip point frame in the world (design notes 1)
  Isometry forearm = Isometry::Identity();    ///< origin at the elbow, z along elbow -> wrist
  Isometry upper_arm = Isometry::Identity();  ///< origin at the shoulder, z along shoulder -> elbow
  /// The trunk (legs, torso box, head): origin on the floor under the body
  /// centre, x forward, z up (io::HumanBodyPoses::torso). Its shapes are sized
  /// by CollisionConfig::person.trunk. A tracker that does not see the trunk
  /// gets it derived from the shoulder and the declared stand (runtime).
  Isometry torso = Isometry::Identity();
  /// false: the trunk is not known (no stand declared); its pairs give no rows.
  bool trunk_valid = false;
  double forearm_length = 0.27;               ///< m, elbow to wrist
  double upper_arm_length = 0.33;             ///< m, shoulder to elbow
  /// Optional twists [v of the frame origin; omega], world axes, m/s and rad/s.
  /// They enter d_dot (a person moving toward the robot shrinks the distance);
  /// the person's acceleration is taken as zero.
  Vector6 hand_velocity = Vector6::Zero();
  Vector6 forearm_velocity = Vector6::Zero();
  Vector6 upper_arm_velocity = Vector6::Zero();
  /// The object the gripper approaches (while the person holds it); false:
  /// pairs with the object give no rows (the robot holds it, or it is not seen).
  bool object_valid = false;
  Isometry object = Isometry::Identity();      ///< object frame in the world (shape centre)
  Vector6 object_velocity = Vector6::Zero();
  /// Where the person's reaching hand will come to rest (grip point frame,
  /// world; perception/reach_predictor.hpp); false: no reach is under way or
  /// its end is not trusted yet, and pairs with the forecast give no rows.
  /// The arm keeps out of the hand's way (from `hand` to here) before the
  /// hand is there.
  bool hand_forecast_valid = false;
  Isometry hand_forecast = Isometry::Identity();
};

}  // namespace handover::control
