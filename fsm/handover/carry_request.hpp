// The request/answer channel between a state that carries a held object and
// the planner's upright-placement search (fsm::PlannerInterface). The search
// costs about 1.5 ms, more than the 1 ms control step, so it never runs in
// the step: the state posts a request when it starts, the planning stage
// (HandoverFsm::plan, called by runtime::HandoverCycle::plan before the next
// step) answers it, and the state adopts the answer in its run().
//
// One slot: a new request replaces one not yet answered. Every request has
// an id, and an answer carries the id of the request it answers, so a state
// adopts only the answer to its own request, never a stale one posted by an
// earlier state (or an earlier start of the same state).
//
// Frames: world; the object's pose in the TCP frame. Units: m, rad.
// Real-time: every method is RT safe (fixed-size storage, no search). On a
// real robot whose planning runs in another thread, guard the channel with
// the same lock as the plans (HandoverCycle::plan).
#pragma once

#include "fsm/handover/grasp_plan.hpp"

namespace handover::fsm {

/// What a state asks the planner: where to hold the object upright.
struct CarryRequest {
  int id = 0;                                     ///< > 0 once posted
  Isometry object_in_tcp = Isometry::Identity();  ///< the held object's pose in the TCP frame
  Vector3 up_axis = Vector3::UnitZ();             ///< object-frame axis to keep along world z (unit)
  Vector3 object_position = Vector3::Zero();      ///< m, world: where the object should go (near)
  Vector7 q = Vector7::Zero();                    ///< rad, the arm when the request was posted
  /// m: a receiver will reach for the object there, their hand stopping this
  /// far from its centre; the placement keeps the arm out of their way (0:
  /// nobody reaches for it)
  double receiver_stop = 0.0;
};

class CarryChannel {
 public:
  /// Posts a request (replacing one not yet answered); returns its id (> 0).
  int post(const Isometry& object_in_tcp, const Vector3& up_axis, const Vector3& object_position, const Vector7& q,
           double receiver_stop = 0.0) {
    request_.id = ++last_id_;
    request_.object_in_tcp = object_in_tcp;
    request_.up_axis = up_axis;
    request_.object_position = object_position;
    request_.q = q;
    request_.receiver_stop = receiver_stop;
    pending_ = true;
    return request_.id;
  }
  /// Drops request `id` if it is still waiting (its state ended first).
  void withdraw(int id) {
    if (pending_ && request_.id == id) pending_ = false;
  }

  /// A request waits for an answer.
  bool pending() const { return pending_; }
  const CarryRequest& request() const { return request_; }
  /// Answers the pending request (the planning stage); ignored without one.
  void answer(const ArmPlacement& placement) {
    if (!pending_) return;
    answer_ = placement;
    answer_id_ = request_.id;
    pending_ = false;
  }

  /// The answer to request `id`, or null while it has none (not answered
  /// yet, withdrawn, or replaced by a newer request before its answer).
  const ArmPlacement* answerTo(int id) const { return id > 0 && answer_id_ == id ? &answer_ : nullptr; }

 private:
  CarryRequest request_;
  bool pending_ = false;
  int last_id_ = 0;
  int answer_id_ = 0;  ///< the request answer_ answers (0: none)
  ArmPlacement answer_;
};

}  // namespace handover::fsm
