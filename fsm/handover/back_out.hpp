// BackOut: after the fingers let go of an object the person keeps, withdraw
// the way they came in - straight back along the approach axis (TCP -z), at
// the current orientation - before turning toward the stow pose. Going
// straight to the stow pose turns the gripper while its fingers still
// straddle the object: they strike it and spin the wrist (joint 7 past its
// velocity limit) or drag it from the person's hand.
#pragma once

#include "fsm/handover/handover_state.hpp"

namespace handover::fsm {

/// [Clear] Tracking off, observation none; pose task to the TCP pose
/// `distance` behind the current one along its z axis. Clear once the TCP
/// has moved back along that axis to within position_tolerance of
/// `distance`. Keys: distance (m), position_tolerance (m); `timeout` (s)
/// gives output Timeout (the transition table decides; usually the same as Clear).
class BackOut : public HandoverState {
 public:
  BackOut();
  void configure(const YamlReader& def) override;
  void onStart(HandoverContext& ctx) override;
  bool onRun(HandoverContext& ctx) override;

 private:
  int clear_;
  double distance_ = 0.08, pos_tol_ = 0.01;
  Isometry start_ = Isometry::Identity();  ///< the TCP when the fingers let go
};

}  // namespace handover::fsm
