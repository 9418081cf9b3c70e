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
  return o;
}

double objectWidthAcrossFingers(const scenario::ObjectSpec& obj) { return scenario::objectWidthAcrossFingers(obj); }

control::GraspOffset graspOffsetFor(const scenario::ObjectSpec& obj) {
  control::GraspOffset g;
  g.placement = obj.grasp;
  if (obj.free_axis >= 0) {
    g.has_free_axis = true;
    g.free_axis = control::Vector3::Unit(obj.free_axis);
  }
  return g;
}

}  // namespace handover::app
