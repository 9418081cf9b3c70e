// Cost of planning a give's presentation (runtime/grasp_planning.hpp): one
// update per new hand sample while the robot holds the object, the hand
// swaying at 60 Hz in front of the robot. Args: the presentation tilt in
// degrees (0: upright only, 12 turns about the hand's vertical; 30, as
// shipped: the upright and the tilted presentation, 24 candidates); and 1 when
// the planner knows the bottle's shape and that it is held 8 cm above its
// centre (each presentation also with the hand on the free part: twice the
// candidates), 0 when not. Runs at the sensor rate, outside the 1 ms control
// step (HandoverCycle::plan).
// BM_TakePlanning: a take's grasp per object sample, a bottle (declared side
// grasp and the cylinder's shape families) swaying in a person's hand, their
// arm and trunk as obstacles with what the shipped collision rules keep, and
// the bottle's own shape (no pre-grasp inside it).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "control/collision/collision_model.hpp"
#include "control/grasp/grasp_selection_config.hpp"
#include "control/grasp/shape_grasps.hpp"
#include "runtime/grasp_planning.hpp"

namespace {

using namespace handover;

const control::Model& pandaModel() {
  static const control::Model model = control::loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  return model;
}

perception::PerceptionEstimate handSample(int k) {
  const double t = k / 60.0;
  perception::PerceptionEstimate e;
  e.time = t;
  e.human.valid = true;
  e.human.stale = false;
  e.human.stamp = t;
  e.human.hand.translation() =
      control::Vector3(0.62 + 0.03 * std::sin(1.3 * t), 0.10 * std::sin(0.9 * t), 0.40 + 0.03 * std::sin(2.1 * t));
  e.human.forearm.translation() = e.human.hand.translation() + control::Vector3(0.25, 0.0, -0.10);
  e.human.upper_arm.translation() = e.human.hand.translation() + control::Vector3(0.35, 0.0, 0.20);
  e.object.valid = true;
  e.object.stale = false;
  e.object.holder = perception::ObjectHolder::Robot;
  return e;
}

void BM_PresentationPlanning(benchmark::State& state) {
  runtime::GraspPlanningSettings s;
  s.config = control::grasp::loadGraspSelectionConfig(std::string(HANDOVER_SOURCE_DIR) + "/config/grasp_selection.yaml");
  s.config.presentation_tilt = state.range(0) * M_PI / 180.0;
  control::grasp::GraspSpec top;  // a bottle held from the top, presented 5 cm above the grip point
  top.placement.linear() = Eigen::AngleAxisd(M_PI, control::Vector3::UnitX()).toRotationMatrix();
  s.object_grasps.push_back(top);
  s.presentation = control::Isometry::Identity();
  s.presentation.linear() = top.placement.linear();
  s.presentation.translation() = control::Vector3(0.0, 0.0, 0.13);
  s.presentation_pivot = control::Vector3(0.0, 0.0, 0.05);
  if (state.range(1) != 0) {  // the grasp 8 cm above the centre of a 22 cm bottle
    s.held_grasp = top.placement;
    s.held_grasp.translation() = control::Vector3(0.0, 0.0, 0.08);
    s.object_shape.kind = io::ObjectShape::Kind::kCylinder;
    s.object_shape.size = control::Vector3(0.033, 0.22, 0.0);
  }
  // the receiver's hand as the shipped collision model has it (config/collision.yaml person.hand)
  // and the gripper's keep from it: the presentation's shortfall is scored
  s.hand_box_half_extents = control::Vector3(0.045, 0.04, 0.015);
  s.keeps.hand.gripper = 0.021;
  s.keeps.hand.arm = 0.04;
  runtime::GraspPlanning planning(pandaModel(), s);
  control::Vector7 q;
  q << 0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398;
  int k = 0;
  planning.update(handSample(k++), q, true);  // the cold first update is not measured
  long planned = 0, updates = 0;
  for (auto _ : state) {
    planning.update(handSample(k++), q, true);
    planned += planning.handPlan().valid;
    ++updates;
    benchmark::DoNotOptimize(planning.handPlan().q_target.data());
  }
  state.counters["planned"] = static_cast<double>(planned) / static_cast<double>(updates);
}
void BM_TakePlanning(benchmark::State& state) {
  runtime::GraspPlanningSettings s;
  s.config = control::grasp::loadGraspSelectionConfig(std::string(HANDOVER_SOURCE_DIR) + "/config/grasp_selection.yaml");
  control::grasp::GraspSpec side;
  side.placement.linear() = Eigen::AngleAxisd(M_PI / 2, control::Vector3::UnitY()).toRotationMatrix();
  side.has_free_axis = true;
  side.preference = s.config.declared_preference;
  s.object_grasps.push_back(side);
  for (const auto& g : control::grasp::shapeGraspSpecs(control::grasp::PrimitiveShape::kCylinder, {0.03, 0.20}))
    s.object_grasps.push_back(g);
  s.object_shape.kind = io::ObjectShape::Kind::kCylinder;  // the bottle itself: no pre-grasp inside it
  s.object_shape.size = control::Vector3(0.03, 0.20, 0.0);
  const control::CollisionConfig cc = control::loadCollisionConfig(control::defaultCollisionConfigPath());
  s.trunk = runtime::trunkObstacles(cc.person.trunk, cc.person.free_arm_radius);
  s.keeps = runtime::personKeeps(control::buildCollisionModel(pandaModel(), cc));
  runtime::GraspPlanning planning(pandaModel(), s);
  control::Isometry torso = control::Isometry::Identity();  // facing the robot, 0.45 m beyond the hand
  torso.linear() = Eigen::AngleAxisd(M_PI, control::Vector3::UnitZ()).toRotationMatrix();
  torso.translation() = control::Vector3(1.07, 0.0, -0.75);
  control::Vector7 q;
  q << 0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398;
  auto sample = [](int k) {
    perception::PerceptionEstimate e = handSample(k);
    e.object.holder = perception::ObjectHolder::Person;
    e.object.pose.translation() = e.human.hand.translation() + control::Vector3(0.0, 0.0, 0.08);
    return e;
  };
  int k = 0;
  planning.update(sample(k++), q, false, &torso);  // the cold first update is not measured
  long planned = 0, updates = 0;
  for (auto _ : state) {
    planning.update(sample(k++), q, false, &torso);
    planned += planning.objectPlan().valid;
    ++updates;
    benchmark::DoNotOptimize(planning.objectPlan().q_target.data());
  }
  state.counters["planned"] = static_cast<double>(planned) / static_cast<double>(updates);
}
BENCHMARK(BM_TakePlanning)->Unit(benchmark::kMicrosecond);

BENCHMARK(BM_PresentationPlanning)->Args({0, 0})->Args({30, 0})->Args({30, 1})->Unit(benchmark::kMicrosecond);

}  // namespace
