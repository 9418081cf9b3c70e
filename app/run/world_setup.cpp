#include "app/run/world_setup.hpp"

#include <cmath>

#include "scenes/scenario/object_geometry.hpp"

namespace handover::app {

std::string sourcePath(const std::string& relative) { return std::string(HANDOVER_SOURCE_DIR) + "/" + relative; }

sim::SimOptions simOptionsFor(const scenario::Scenario& sc) {
  sim::SimOptions o;
  switch (sc.object.shape) {
    case scenario::Shape::Cylinder: o.object.shape = sim::ObjectShape::Cylinder; break;
    case scenario::Shape::Box: o.object.shape = sim::ObjectShape::Box; break;
    case scenario::Shape::Sphere: o.object.shape = sim::ObjectShape::Sphere; break;
  }
  o.object.size = sc.object.size;
  o.object.mass = sc.object.mass;
  const scenario::BodyDimensions body = scenario::bodyDimensionsFromHeight(sc.human.height);
  o.human.height = sc.human.height;
  o.human.upper_arm_length = body.upper_arm;
  o.human.forearm_length = body.forearm;
  o.human.hand = sc.human.hand;
  return o;
}


control::GraspOffset graspOffsetFor(const scenario::ObjectSpec& obj) {
  control::GraspOffset g;
  g.placement = obj.grasp;
  if (obj.free_axis >= 0) {
    g.has_free_axis = true;
    g.free_axis = control::Vector3::Unit(obj.free_axis);
  }
  return g;
}

control::ObjectShapeSettings collisionShapeFor(const scenario::ObjectSpec& obj) {
  control::ObjectShapeSettings o;
  const std::vector<double>& s = obj.size;
  switch (obj.shape) {
    case scenario::Shape::Box:
      o.shape.kind = control::ShapeSpec::Kind::kBox;
      o.shape.size = control::Vector3(s[0], s[1], s[2]);
      o.radius = 0.0;
      break;
    case scenario::Shape::Cylinder:  // a box around it: flat ends, like the cylinder's
      o.shape.kind = control::ShapeSpec::Kind::kBox;
      o.shape.size = control::Vector3(2.0 * s[0], 2.0 * s[0], s[1]);
      o.radius = 0.0;
      break;
    case scenario::Shape::Sphere:
      o.shape.kind = control::ShapeSpec::Kind::kSegment;
      o.shape.length = 0.0;
      o.radius = s[0];
      break;
  }
  return o;
}

std::vector<control::grasp::GraspSpec> graspSpecsFor(const scenario::ObjectSpec& obj, double declared_preference,
                                                     double gripper_opening, const control::grasp::PalmGeometry& palm) {
  namespace cg = control::grasp;
  auto declared = [&](const Eigen::Isometry3d& grasp, int free_axis) {
    cg::GraspSpec s;
    s.placement = grasp;
    s.has_free_axis = free_axis >= 0;
    if (s.has_free_axis) s.free_axis = control::Vector3::Unit(free_axis);
    s.preference = declared_preference;
    return s;
  };
  const cg::PrimitiveShape shape = obj.shape == scenario::Shape::Box        ? cg::PrimitiveShape::kBox
                                   : obj.shape == scenario::Shape::Sphere ? cg::PrimitiveShape::kSphere
                                                                          : cg::PrimitiveShape::kCylinder;
  // a declared grasp deeper than the palm lets the fingers go is taken as deep as it does
  const io::ObjectShape solid = scenario::primitiveShapeOf(obj);
  const auto fitted = [&](const Eigen::Isometry3d& grasp) { return cg::fitToPalm(solid, grasp, palm); };
  std::vector<cg::GraspSpec> specs{declared(fitted(obj.grasp), obj.free_axis)};
  for (const scenario::ObjectSpec::ExtraGrasp& g : obj.grasps) specs.push_back(declared(fitted(g.grasp), g.free_axis));
  // and every family the shape allows (a person may hold it anywhere)
  cg::ShapeGraspOptions options;
  options.max_opening = gripper_opening;
  for (const cg::GraspSpec& g : cg::shapeGraspSpecs(shape, obj.size, options)) specs.push_back(g);
  return specs;
}

scenario::ObjectSpec robotHeldObject(const scenario::Scenario& sc, const control::grasp::PalmGeometry& palm) {
  scenario::ObjectSpec held = sc.object;
  if (sc.robot.holds_object) held.grasp = control::grasp::fitToPalm(scenario::primitiveShapeOf(sc.object), sc.object.grasp, palm);
  return held;
}

}  // namespace handover::app
