#include "runtime/grasp_planning.hpp"

#include "control/grasp/upright_placement.hpp"

namespace handover::runtime {

namespace cg = control::grasp;

cg::GraspSelectionConfig presentationSelectionConfig(cg::GraspSelectionConfig config) {
  config.candidates.parallel_gripper_twin = false;
  // the object is brought straight to the hand (ApproachHand has no standoff):
  // a pre-grasp 8 cm back along the approach axis, out of reach above a high
  // hand, left the presentation unplanned and the arm's wrist in its limit
  config.candidates.pre_grasp_standoff = 0.0;
  return config;
}

namespace {
std::vector<cg::GraspSpec> presentationSpecs(const control::Isometry& presentation, const control::Vector3& pivot,
                                             const cg::GraspSelectionConfig& config) {
  cg::GraspSpec upright;
  upright.placement = presentation;
  upright.has_free_axis = true;  // any turn about the hand's vertical
  upright.free_axis = control::Vector3::UnitZ();
  if (!(config.presentation_tilt > 0.0)) return {upright};
  upright.preference = config.declared_preference;
  // tilted about the hand's x axis through the object's centre; the free turn
  // about the vertical sweeps the tilt through every direction
  cg::GraspSpec tilted = upright;
  tilted.preference = 0.0;
  tilted.placement = Eigen::Translation3d(pivot) *
                     Eigen::AngleAxisd(config.presentation_tilt, control::Vector3::UnitX()) *
                     Eigen::Translation3d(-pivot) * presentation;
  return {upright, tilted};
}
}  // namespace

GraspPlanning::GraspPlanning(const control::Model& model, const GraspPlanningSettings& settings)
    : model_(model),
      settings_(settings),
      object_(model, settings.object_grasps, settings.config),
      hand_(model, presentationSpecs(settings.presentation, settings.presentation_pivot, settings.config),
            presentationSelectionConfig(settings.config)) {}

void GraspPlanning::reset() {
  object_.reset();
  hand_.reset();
  object_plan_ = fsm::TrackingPlan{};
  hand_plan_ = fsm::TrackingPlan{};
  object_stamp_ = hand_stamp_ = -1.0;
}

void GraspPlanning::copyChoice(const cg::GraspChoice& c, fsm::TrackingPlan& plan) {
  plan.valid = c.valid;
  if (!c.valid) return;  // keep the last choice's values for logs; states ignore an invalid plan
  plan.index = c.index;
  plan.target_in_observed = c.grasp_in_object;
  plan.q_target = c.q_grasp;
  plan.q_pre = c.q_pre_grasp;
}

int GraspPlanning::personObstacles(const perception::HumanEstimate& human, bool with_hand) {
  if (!human.valid || human.stale) return 0;
  auto capsule = [](const control::Isometry& X, double length, double radius) {
    cg::ObstacleCapsule c;
    c.a = X.translation();
    c.b = X * control::Vector3(0.0, 0.0, length);  // the segment runs along the body's z axis
    c.radius = radius;
    return c;
  };
  obstacles_[0] = capsule(human.forearm, settings_.forearm_length, settings_.forearm_radius);
  obstacles_[1] = capsule(human.upper_arm, settings_.upper_arm_length, settings_.upper_arm_radius);
  if (!with_hand) return 2;
  obstacles_[2] = capsule(human.hand, 0.0, settings_.hand_radius);
  obstacles_[2].gripper_works_here = true;  // the fingers work in it; the palm and the arm keep clear
  return 3;
}

void GraspPlanning::update(const perception::PerceptionEstimate& est, const control::Vector7& q, bool robot_holds) {
  const bool fresh_sample = est.human.valid && !est.human.stale;
  if (!robot_holds) {
    if (fresh_sample && est.object.valid && est.human.stamp != object_stamp_) {
      object_stamp_ = est.human.stamp;
      const int n = personObstacles(est.human, true);
      copyChoice(object_.update(est.object.pose, q, obstacles_, n), object_plan_);
    }
    hand_plan_.valid = false;
    return;
  }
  if (fresh_sample && est.human.stamp != hand_stamp_) {
    hand_stamp_ = est.human.stamp;
    const int n = personObstacles(est.human, false);  // the object goes into that hand
    copyChoice(hand_.update(est.human.hand, q, obstacles_, n), hand_plan_);
  }
  object_plan_.valid = false;
}

fsm::ArmPlacement GraspPlanning::uprightPlacement(const control::Isometry& object_in_tcp,
                                                  const control::Vector3& up_axis,
                                                  const control::Vector3& object_position,
                                                  const control::Vector7& q_now) {
  cg::HeldObject held;
  held.object_in_tcp = object_in_tcp;
  held.up_axis = up_axis;
  const cg::UprightPlacement p = cg::findUprightPlacement(model_, held, object_position, q_now, settings_.config);
  fsm::ArmPlacement out;
  out.found = p.found;
  out.tcp = p.tcp;
  out.q = p.q;
  return out;
}

}  // namespace handover::runtime
