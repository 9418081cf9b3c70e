#include "control/collision/collision_data.hpp"

namespace handover::control {

namespace {
std::vector<ShapeSpec> shapesOf(const CollisionModel& model) {
  std::vector<ShapeSpec> s;
  s.reserve(model.bodies.size());
  for (const auto& b : model.bodies) s.push_back(b.shape);
  return s;
}
}  // namespace

CollisionData::CollisionData(const CollisionModel& model)
    : shapes(shapesOf(model)),
      body_pose(model.bodies.size(), Isometry::Identity()),
      body_twist(model.bodies.size(), Vector6::Zero()),
      rule_enabled(model.rule_enabled),
      results(model.pairs.size()),
      last_normal(model.pairs.size(), Vector3::UnitZ()),
      has_last_normal(model.pairs.size(), false) {}

}  // namespace handover::control
