// Slip detection: the robot is losing the object it holds (an interrupt
// condition; config/fsm.yaml preempts into the Lost rest state, outcome
// failed).
#pragma once

#include "fsm/core/condition.hpp"
#include "fsm/handover/handover_context.hpp"

namespace handover::fsm {

/// Holds while the robot holds the object (payload set, fingers commanded
/// closed) and, for hold_time, either
///  - the fingers have closed by more than width_drop (m) below the widest
///    opening seen while holding: the object slid out from between them, or
///  - the person's hand is farther than hand_clearance (m) from the TCP (so
///    nobody else carries it) and the robot's load share is below min_share,
///    with the whole load force below min_share of the weight too: the
///    weight left the gripper (a push on the object only turned it).
/// Keys: width_drop (m), min_share (0..1), hand_clearance (m), hold_time (s).
/// RT safe.
class ObjectLost : public Condition {
 public:
  void configure(const YamlReader& def) override;
  bool evaluate(Context& ctx) override;

 private:
  double width_drop_ = 0.01, min_share_ = 0.3, hand_clearance_ = 0.2, hold_time_ = 0.1;
  double held_width_ = -1.0;  ///< m, widest finger opening while holding; < 0: not holding
  double since_ = -1.0;
};

}  // namespace handover::fsm
