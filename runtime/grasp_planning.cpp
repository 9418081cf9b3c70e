#include "runtime/grasp_planning.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "control/grasp/upright_placement.hpp"

namespace handover::runtime {

namespace cg = control::grasp;

cg::GraspSelectionConfig presentationSelectionConfig(cg::GraspSelectionConfig config) {
  config.candidates.parallel_gripper_twin = false;
  // the object is brought straight to the hand (ApproachHand has no standoff):
  // a pre-grasp 8 cm back along the approach axis, out of reach above a high
  // hand, left the presentation unplanned and the arm's wrist in its limit
  config.candidates.pre_grasp_standoff = 0.0;
  // the receiver comes to the object: their arm where it is now does not rule a presentation out
  // (seeds 1 and 12 with the rule: 17 gives lost, 7 gained)
  config.reject_inside_keeps = false;
  return config;
}

namespace {
// what the constraints keep from that obstacle, apart and while the fingers share the object
void applyKeep(cg::ObstacleCapsule& o, const PersonKeeps::Keep& k) {
  o.keep_arm = k.arm;
  o.keep_gripper = k.gripper;
  o.keep_arm_sharing = k.arm_sharing;
  o.keep_gripper_sharing = k.gripper_sharing;
}

std::vector<cg::GraspSpec> declaredPresentations(const control::Isometry& presentation, const control::Vector3& pivot,
                                                 const cg::GraspSelectionConfig& config) {
  cg::GraspSpec upright;
  upright.placement = presentation;
  upright.has_free_axis = true;  // any turn about the hand's vertical
  upright.free_axis = control::Vector3::UnitZ();
  if (!(config.presentation_tilt > 0.0)) return {upright};
  upright.preference = config.declared_preference;
  // tilted about the hand's x or y axis through the object's centre; the free
  // turn about the vertical sweeps each tilt through every direction. Two axes:
  // the gripper turns with the object, and a tilt about the axis its fingers
  // close along keeps them level over the palm where a tilt across it dips
  // one fingertip toward the palm (shortfall in the score)
  std::vector<cg::GraspSpec> specs{upright};
  for (const control::Vector3 axis : {control::Vector3::UnitX(), control::Vector3::UnitY()}) {
    cg::GraspSpec tilted = upright;
    tilted.preference = 0.0;
    tilted.placement = Eigen::Translation3d(pivot) * Eigen::AngleAxisd(config.presentation_tilt, axis) *
                       Eigen::Translation3d(-pivot) * presentation;
    specs.push_back(tilted);
  }
  return specs;
}
}  // namespace

std::vector<cg::GraspSpec> presentationSpecs(const GraspPlanningSettings& settings) {
  std::vector<cg::GraspSpec> specs =
      declaredPresentations(settings.presentation, settings.presentation_pivot, settings.config);
  // the grasp point seen from the object's centre (object frame); the free part lies opposite
  const control::Vector3 g = settings.held_grasp.translation();
  constexpr double kNearCentre = 0.02;  // m: a grasp this near the centre leaves no end free of it
  if (!settings.object_shape.known() || g.norm() < kNearCentre) return specs;
  const control::Vector3 away = -g.normalized();
  const control::Vector3 free_point = 0.5 * io::exitDistance(settings.object_shape, control::Vector3::Zero(), away) * away;
  const std::size_t declared = specs.size();
  for (std::size_t k = 0; k < declared; ++k) {
    // the object in the hand frame for this presentation; moved so that its free point is at the grip point
    const control::Isometry object = specs[k].placement * settings.held_grasp.inverse();
    cg::GraspSpec shifted = specs[k];
    shifted.preference = 0.0;
    shifted.placement = Eigen::Translation3d(-(object * free_point)) * specs[k].placement;
    specs.push_back(shifted);
  }
  return specs;
}

control::Vector3 receiverPull(const perception::HumanEstimate& person) {
  control::Vector3 d = person.upper_arm.translation() - person.hand.translation();
  d.z() = 0.0;
  const double n = d.norm();
  return n > 1e-6 ? control::Vector3(d / n) : control::Vector3::Zero();
}

PersonKeeps personKeeps(const control::CollisionModel& model) {
  PersonKeeps k;
  for (const control::CollisionPair& p : model.pairs) {
    const control::RuleScope scope = model.rule_scope[static_cast<std::size_t>(p.rule)];
    PersonKeeps::Keep* keep = nullptr;
    switch (model.bodies[static_cast<std::size_t>(p.other_body)].kind) {
      case control::CollisionBodyKind::kHumanHand: keep = &k.hand; break;
      case control::CollisionBodyKind::kHumanForearm: keep = &k.forearm; break;
      case control::CollisionBodyKind::kHumanUpperArm: keep = &k.upper_arm; break;
      case control::CollisionBodyKind::kHumanTrunk: keep = &k.trunk; break;
      case control::CollisionBodyKind::kObject: keep = &k.object; break;
      default: continue;
    }
    const double d = p.margin + p.damper.s_dist;
    const bool arm = model.bodies[static_cast<std::size_t>(p.robot_body)].role == control::CapsuleRole::kArm;
    if (!control::whileSharing(scope)) {
      double& slot = arm ? keep->arm : keep->gripper;
      slot = std::max(slot, d);
    }
    if (scope != control::RuleScope::kApart) {
      double& slot = arm ? keep->arm_sharing : keep->gripper_sharing;
      slot = std::max(slot, d);
    }
  }
  return k;
}

cg::ObstacleCapsule heldObjectObstacle(const io::ObjectShape& shape, const control::Isometry& pose,
                                       const PersonKeeps::Keep& keep) {
  cg::ObstacleCapsule o;
  o.held_object = true;
  applyKeep(o, keep);
  o.a = o.b = pose.translation();
  const control::Vector3& size = shape.size;
  switch (shape.kind) {
    case io::ObjectShape::Kind::kSphere:
      o.radius = size.x();
      break;
    case io::ObjectShape::Kind::kCylinder: {
      const double r = size.x(), half_h = 0.5 * size.y();
      if (half_h >= r) {
        o.radius = r;
        o.a = pose * control::Vector3(0.0, 0.0, -(half_h - r));
        o.b = pose * control::Vector3(0.0, 0.0, half_h - r);
      } else {
        o.box_axes = pose.linear();
        o.box_half_extents = control::Vector3(r * M_SQRT1_2, r * M_SQRT1_2, half_h);
      }
      break;
    }
    case io::ObjectShape::Kind::kBox:
      o.box_axes = pose.linear();
      o.box_half_extents = 0.5 * size;
      break;
    case io::ObjectShape::Kind::kUnknown:
      break;
  }
  return o;
}

std::vector<cg::ObstacleCapsule> trunkObstacles(const control::PersonTrunk& trunk, double free_arm_radius) {
  std::vector<cg::ObstacleCapsule> out;
  const control::Vector3& size = trunk.torso_size;  // depth (x), width (y), height (z)
  const double r = 0.5 * std::min(size.x(), size.y());
  const double half_z = std::max(0.0, 0.5 * size.z() - r);
  // the narrower side's half-width swept along the wider one: two capsules at its ends
  const control::Vector3 along = size.x() < size.y() ? control::Vector3::UnitY() : control::Vector3::UnitX();
  const double offset = 0.5 * std::max(size.x(), size.y()) - r;
  for (double side : {-1.0, 1.0}) {
    cg::ObstacleCapsule c;
    const control::Vector3 centre = control::Vector3(0.0, 0.0, trunk.torso_centre) + side * offset * along;
    c.a = centre - half_z * control::Vector3::UnitZ();
    c.b = centre + half_z * control::Vector3::UnitZ();
    c.radius = r;
    out.push_back(c);
  }
  cg::ObstacleCapsule head;
  head.a = head.b = control::Vector3(0.0, 0.0, trunk.head_centre);
  head.radius = trunk.head_radius;
  out.push_back(head);
  cg::ObstacleCapsule arm;
  arm.a = trunk.free_arm_top;
  arm.b = trunk.free_arm_bottom;
  arm.radius = free_arm_radius;
  out.push_back(arm);
  return out;
}

GraspPlanning::GraspPlanning(const control::Model& model, const GraspPlanningSettings& settings)
    : model_(model),
      settings_(settings),
      object_(model, settings.object_grasps, settings.config),
      hand_(model, presentationSpecs(settings),
            presentationSelectionConfig(settings.config)) {
  if (static_cast<int>(settings.trunk.size()) > kMaxTrunkObstacles)
    throw std::invalid_argument("GraspPlanning: more trunk capsules than kMaxTrunkObstacles");
}

void GraspPlanning::reset() {
  object_.reset();
  hand_.reset();
  object_plan_ = fsm::TrackingPlan{};
  hand_plan_ = fsm::TrackingPlan{};
  object_stamp_ = hand_stamp_ = -1.0;
  last_person_.reset();
  last_torso_.reset();
}

void GraspPlanning::copyChoice(const cg::GraspChoice& c, fsm::TrackingPlan& plan) {
  plan.valid = c.valid;
  if (!c.valid) return;  // keep the last choice's values for logs; states ignore an invalid plan
  plan.index = c.index;
  plan.target_in_observed = c.grasp_in_object;
  plan.q_target = c.q_grasp;
  plan.q_pre = c.q_pre_grasp;
}

cg::ObstacleCapsule holdingHandObstacle(const GraspPlanningSettings& settings, const control::Isometry& hand) {
  cg::ObstacleCapsule o;
  if (settings.hand_box_half_extents.isZero()) {
    o.a = o.b = hand.translation();
    o.radius = settings.hand_radius;
  } else {
    const control::Isometry X = hand * settings.hand_box;
    o.a = o.b = X.translation();
    o.box_axes = X.linear();
    o.box_half_extents = settings.hand_box_half_extents;
  }
  o.gripper_works_here = true;
  applyKeep(o, settings.keeps.hand);
  return o;
}

int GraspPlanning::trunkObstacles(const control::Isometry* torso) const {
  return torso == nullptr ? 0 : static_cast<int>(settings_.trunk.size());
}

int GraspPlanning::personObstacles(const perception::HumanEstimate& human, bool holding_hand,
                                   const control::Isometry* torso) {
  if (!human.valid || human.stale) return 0;
  auto capsule = [](const control::Isometry& X, double length, double radius) {
    cg::ObstacleCapsule c;
    c.a = X.translation();
    c.b = X * control::Vector3(0.0, 0.0, length);  // the segment runs along the body's z axis
    c.radius = radius;
    return c;
  };
  obstacles_[0] = capsule(human.forearm, settings_.forearm_length, settings_.forearm_radius);
  applyKeep(obstacles_[0], settings_.keeps.forearm);
  obstacles_[1] = capsule(human.upper_arm, settings_.upper_arm_length, settings_.upper_arm_radius);
  applyKeep(obstacles_[1], settings_.keeps.upper_arm);
  int n = 2;
  if (holding_hand) {
    // the hand that holds the object: the fingers work in it, the palm and the arm keep clear. Of
    // the hand the constraints see (its box), not of a sphere around it: the sphere reached 3 cm
    // past the palm's faces and ruled out every grasp of balls and boxes held low, by 0.3-8 mm
    // (g1101_00613, g1109_00061), and the arm stalled at the declared grasp until the person gave up
    obstacles_[2] = holdingHandObstacle(settings_, human.hand);
    n = 3;
  } else if (!settings_.hand_box_half_extents.isZero()) {
    // the hand the object goes into: the fingers come as near as the constraints let them (keepShortfall)
    // (the same box as a take's holding hand, counted for its keeps only)
    cg::ObstacleCapsule& box = obstacles_[2];
    box = holdingHandObstacle(settings_, human.hand);
    box.gripper_works_here = false;
    box.keep_only = true;
    n = 3;
  }
  if (torso == nullptr) return n;
  for (const cg::ObstacleCapsule& c : settings_.trunk) {
    cg::ObstacleCapsule& o = obstacles_[n++];
    o = c;
    o.a = *torso * c.a;
    o.b = *torso * c.b;
    applyKeep(o, settings_.keeps.trunk);
  }
  return n;
}

void GraspPlanning::update(const perception::PerceptionEstimate& est, const control::Vector7& q, bool robot_holds,
                           const control::Isometry* torso) {
  const bool fresh_sample = est.human.valid && !est.human.stale;
  if (fresh_sample) {
    last_person_ = est.human;
    if (torso != nullptr) last_torso_ = *torso;
  }
  if (!robot_holds) {
    if (fresh_sample && est.object.valid && est.human.stamp != object_stamp_) {
      object_stamp_ = est.human.stamp;
      int n = personObstacles(est.human, true, torso);
      // the object itself: where the arm lines up, the gripper is still in front of it
      if (settings_.object_shape.known())
        obstacles_[static_cast<std::size_t>(n++)] =
            heldObjectObstacle(settings_.object_shape, est.object.pose, settings_.keeps.object);
      copyChoice(object_.update(est.object.pose, q, obstacles_.data(), n), object_plan_);
    }
    hand_plan_.valid = false;
    return;
  }
  if (fresh_sample && est.human.stamp != hand_stamp_) {
    hand_stamp_ = est.human.stamp;
    // the object goes into that hand; the presentation is scored against the receiver's arm (it comes to
    // the object) and, where the trunk is known, held short by it only (keep_only: the constraints keep
    // the arm from it; a presentation turned to keep the fingers off the forearm put link 7 at the chest)
    const int n = personObstacles(est.human, false, torso);
    for (int k = n - trunkObstacles(torso); k < n; ++k) obstacles_[static_cast<std::size_t>(k)].keep_only = true;
    hand_.setPullDirection(receiverPull(est.human));
    copyChoice(hand_.update(est.human.hand, q, obstacles_.data(), n), hand_plan_);
  }
  object_plan_.valid = false;
}

fsm::ArmPlacement GraspPlanning::uprightPlacement(const control::Isometry& object_in_tcp,
                                                  const control::Vector3& up_axis,
                                                  const control::Vector3& object_position,
                                                  const control::Vector7& q_now, double receiver_stop) {
  cg::HeldObject held;
  held.object_in_tcp = object_in_tcp;
  held.up_axis = up_axis;
  int n = 0;
  if (receiver_stop > 0.0 && last_person_) {
    // their hand now is not where it will be: it comes along the reach
    n = personObstacles(*last_person_, false, last_torso_ ? &*last_torso_ : nullptr);
    const control::Vector3 shoulder = last_person_->upper_arm.translation();
    const control::Vector3 to_object = object_position - shoulder;
    const double length = to_object.norm() - receiver_stop - settings_.hand_radius;
    if (length > 0.0) {
      cg::ObstacleCapsule& reach = obstacles_[static_cast<std::size_t>(n++)];
      reach = cg::ObstacleCapsule{};
      reach.a = shoulder;
      reach.b = shoulder + to_object.normalized() * length;
      reach.radius = settings_.hand_radius;
      reach.gripper_works_here = true;  // the fingers hold the object where it ends; the palm and the arm keep out
    }
  }
  const cg::UprightPlacement p =
      cg::findUprightPlacement(model_, held, object_position, q_now, settings_.config, obstacles_.data(), n);
  fsm::ArmPlacement out;
  out.found = p.found;
  out.tcp = p.tcp;
  out.q = p.q;
  return out;
}

}  // namespace handover::runtime
