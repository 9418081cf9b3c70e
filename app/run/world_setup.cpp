#include "app/run/world_setup.hpp"

#include <cmath>

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

double objectWidthAcrossFingers(const scenario::ObjectSpec& obj) {
  const Eigen::Vector3d y_obj = obj.grasp.linear().col(1);  // finger closing axis in the object frame
  switch (obj.shape) {
    case scenario::Shape::Sphere: return 2.0 * obj.size[0];
    case scenario::Shape::Cylinder:
      // across the axis: the diameter; along it: the height
      return std::abs(y_obj.z()) > 0.7 ? obj.size[1] : 2.0 * obj.size[0];
    case scenario::Shape::Box:
      return std::abs(y_obj.x()) * obj.size[0] + std::abs(y_obj.y()) * obj.size[1] + std::abs(y_obj.z()) * obj.size[2];
  }
  return 0.08;
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

}  // namespace handover::app
