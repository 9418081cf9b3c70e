#include "fsm/handover/object_lost.hpp"

#include <algorithm>

#include "fsm/handover/perception_checks.hpp"

namespace handover::fsm {

void ObjectLost::configure(const YamlReader& def) {
  const YamlReader w = def.child("width_drop");
  width_drop_ = w.checkRange(w.asDouble(), 0.001, 0.08);
  const YamlReader s = def.child("min_share");
  min_share_ = s.checkRange(s.asDouble(), 0.0, 1.0);
  const YamlReader c = def.child("hand_clearance");
  hand_clearance_ = c.checkRange(c.asDouble(), 0.0, 2.0);
  const YamlReader t = def.child("hold_time");
  hold_time_ = t.checkRange(t.asDouble(), 0.0, 5.0);
}

bool ObjectLost::evaluate(Context& context) {
  const HandoverContext& h = static_cast<HandoverContext&>(context);
  const bool closed = h.ledger->gripperWidth() >= 0.0 && h.ledger->gripperWidth() < 0.5 * h.params->gripper_open_width;
  if (!h.ledger->payloadSet() || !closed) {
    held_width_ = since_ = -1.0;
    return false;
  }
  held_width_ = std::max(held_width_, h.in.finger_width);
  const bool fingers_closed_in = h.in.finger_width < held_width_ - width_drop_;
  const bool hand_away = !h.in.hand.valid || positionError(h.in.hand.pose, h.in.tcp_pose) > hand_clearance_;
  // the weight is gone when nothing loads the gripper any more: the load's whole force, not
  // its vertical share alone (a push on the held object from below or aside, the arm meeting
  // something, took the share to 0 with the object still between the fingers, g1_00505)
  const double weight = h.object.mass * h.params->gravity;
  const bool weight_gone = hand_away && h.in.load_share < min_share_ &&
                           h.in.tool_contact.head<3>().norm() < min_share_ * weight;
  if (!fingers_closed_in && !weight_gone) {
    since_ = -1.0;
    return false;
  }
  if (since_ < 0.0) since_ = h.time;
  return h.time - since_ >= hold_time_;
}

}  // namespace handover::fsm
