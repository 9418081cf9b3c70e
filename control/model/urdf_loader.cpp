// loadModel(): URDF -> Model. The XML is pre-checked with tinyxml so that the
// most common mistakes get a message naming the joint and attribute; urdfdom
// then builds the tree, which we walk from the description's base link (its
// links_/joints_ are maps in name order, not chain order).
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include "config/input_error.hpp"
#include "control/model/model.hpp"
#include "control/model/robot_description.hpp"
#include "control/model/rigid_inertia.hpp"

namespace handover::control {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(path + ": " + what);
}

Isometry toIsometry(const urdf::Pose& p) {
  Isometry X = Isometry::Identity();
  X.linear() = Quaternion(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized().toRotationMatrix();
  X.translation() = Vector3(p.position.x, p.position.y, p.position.z);
  return X;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail(path, "cannot open the URDF file (missing or unreadable)");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Checks well-formedness and that every movable joint carries complete limits,
// which urdfdom would otherwise reject with a message only on the console.
void precheckXml(const std::string& path, const std::string& xml) {
  TiXmlDocument doc;
  doc.Parse(xml.c_str());
  if (doc.Error()) {
    fail(path, "XML error at line " + std::to_string(doc.ErrorRow()) + ": " + doc.ErrorDesc());
  }
  const TiXmlElement* robot = doc.RootElement();
  if (robot == nullptr || std::string(robot->Value()) != "robot") fail(path, "root element is not <robot>");
  for (const TiXmlElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    const char* name = j->Attribute("name");
    const char* type = j->Attribute("type");
    const std::string jn = name ? name : "?";
    if (type == nullptr) fail(path, "joint '" + jn + "' has no type");
    const std::string t = type;
    if (t != "revolute" && t != "prismatic") continue;
    const TiXmlElement* limit = j->FirstChildElement("limit");
    if (limit == nullptr) fail(path, "joint '" + jn + "' (" + t + ") has no <limit> element");
    for (const char* attr : {"lower", "upper", "effort", "velocity"}) {
      double value = 0.0;
      if (limit->QueryDoubleAttribute(attr, &value) != TIXML_SUCCESS) {
        fail(path, "joint '" + jn + "': <limit> lacks a numeric '" + attr + "' attribute");
      }
      if (!std::isfinite(value)) fail(path, "joint '" + jn + "': <limit> " + attr + " is not finite");
    }
  }
}

Inertia linkInertia(const urdf::Link& link) {
  Inertia in;
  if (!link.inertial) return in;
  const urdf::Inertial& u = *link.inertial;
  Inertia local;
  local.mass = u.mass;
  local.inertia_com << u.ixx, u.ixy, u.ixz,
                       u.ixy, u.iyy, u.iyz,
                       u.ixz, u.iyz, u.izz;
  // the inertial origin's rotation turns the tensor's axes into link axes
  return transformInertia(local, toIsometry(u.origin));
}

std::string capsuleBaseName(const std::string& link_name, const std::string& prefix) {
  return link_name.compare(0, prefix.size(), prefix) == 0 ? link_name.substr(prefix.size()) : link_name;
}

// Collision cylinders of `link` as capsules on `body`; X = link frame in the body frame.
void addCapsules(const std::string& path, const urdf::Link& link, int body, const Isometry& X, const std::string& prefix,
                 Model& model) {
  const auto& cols = link.collision_array;
  for (std::size_t k = 0; k < cols.size(); ++k) {
    const urdf::Collision& c = *cols[k];
    if (!c.geometry) fail(path, "link '" + link.name + "': collision without geometry");
    double radius = 0.0, length = 0.0;
    if (c.geometry->type == urdf::Geometry::CYLINDER) {
      const auto& cyl = static_cast<const urdf::Cylinder&>(*c.geometry);
      radius = cyl.radius;
      length = cyl.length;  // distance between sphere centres (capsule convention)
    } else if (c.geometry->type == urdf::Geometry::SPHERE) {
      radius = static_cast<const urdf::Sphere&>(*c.geometry).radius;
    } else {
      fail(path, "link '" + link.name + "': collision geometry must be a <cylinder> (read as a capsule) "
                 "or a <sphere>; see docs/robot-description.md");
    }
    if (!(radius > 0.0) || !(length >= 0.0)) {
      fail(path, "link '" + link.name + "': collision capsule needs radius > 0 and length >= 0");
    }
    const Isometry Xc = X * toIsometry(c.origin);
    Capsule cap;
    cap.name = capsuleBaseName(link.name, prefix);
    if (cols.size() > 1) cap.name += std::string("_") + static_cast<char>('a' + k);
    cap.link = link.name;
    cap.body = body;
    cap.a = Xc * Vector3(0.0, 0.0, -0.5 * length);
    cap.b = Xc * Vector3(0.0, 0.0, 0.5 * length);
    cap.radius = radius;
    model.capsules.push_back(cap);
  }
}

// Everything below link 7: fixed joints and the prismatic finger joints.
// `tool` (body-7 frame) also collects the links from `tool_link` down.
void mergeSubtree(const std::string& path, const urdf::ModelInterface& urdf, const urdf::Link& link,
                  const Isometry& X, const std::string& prefix, Model& model, Inertia& body7, double& finger_max,
                  const std::string& tool_link, Inertia& tool, bool in_tool) {
  for (const auto& joint : link.child_joints) {
    const urdf::LinkConstSharedPtr child = urdf.getLink(joint->child_link_name);
    if (!child) fail(path, "joint '" + joint->name + "' names a missing child link");
    Isometry Xc = X * toIsometry(joint->parent_to_joint_origin_transform);
    if (joint->type == urdf::Joint::PRISMATIC) {
      const double lo = joint->limits->lower, hi = joint->limits->upper;
      const double s = std::min(std::max(0.5 * model.finger_opening, lo), hi);
      const Vector3 axis(joint->axis.x, joint->axis.y, joint->axis.z);
      Xc = Xc * Eigen::Translation3d(s * axis.normalized());
      finger_max += hi;
    } else if (joint->type != urdf::Joint::FIXED) {
      fail(path, "joint '" + joint->name + "' below the last arm link must be fixed or a prismatic finger joint");
    }
    const Inertia child_inertia = transformInertia(linkInertia(*child), Xc);
    body7 = combineInertia(body7, child_inertia);
    const bool child_in_tool = in_tool || child->name == tool_link;
    if (child_in_tool) tool = combineInertia(tool, child_inertia);
    model.frames.push_back(Frame{child->name, kArmDofs, Xc});
    addCapsules(path, *child, kArmDofs, Xc, prefix, model);
    mergeSubtree(path, urdf, *child, Xc, prefix, model, body7, finger_max, tool_link, tool, child_in_tool);
  }
}

// Gripper and fingertip roles of the capsules, from the description's names.
void assignCapsuleRoles(const std::string& path, const RobotDescription& d, Model& model) {
  const std::string from = d.file.empty() ? std::string("the robot description") : d.file;
  for (const std::string& link : d.gripper_links) {
    if (!model.hasFrame(link)) fail(path, "no link '" + link + "' (a gripper link of " + from + ")");
  }
  for (Capsule& c : model.capsules) {
    for (const std::string& link : d.gripper_links)
      if (c.link == link) c.role = CapsuleRole::kGripper;
  }
  for (const std::string& name : d.fingertip_capsules) {
    bool found = false;
    for (Capsule& c : model.capsules) {
      if (c.name != name) continue;
      if (c.role != CapsuleRole::kGripper) {
        fail(path, "capsule '" + name + "' (a fingertip capsule of " + from + ") is not on a gripper link");
      }
      c.role = CapsuleRole::kFingertip;
      found = true;
    }
    if (!found) fail(path, "no collision capsule '" + name + "' (a fingertip capsule of " + from + ")");
  }
}

// The description's link groups; a name without wildcards must be a link or capsule.
void assignLinkGroups(const std::string& path, const RobotDescription& d, Model& model) {
  const std::string from = d.file.empty() ? std::string("the robot description") : d.file;
  for (const LinkGroup& g : d.link_groups) {
    for (const std::string& p : g.patterns) {
      if (p.find_first_of("*?") != std::string::npos || model.hasFrame(p)) continue;
      bool capsule = false;
      for (const Capsule& c : model.capsules) capsule = capsule || c.name == p;
      if (!capsule) fail(path, "no link or capsule '" + p + "' (link group '" + g.name + "' of " + from + ")");
    }
  }
  model.link_groups = d.link_groups;
}

}  // namespace

Model loadModel(const std::string& urdf_path) { return loadModel(urdf_path, Model{}.finger_opening); }

Model loadModel(const std::string& urdf_path, double finger_opening) {
  return loadModel(urdf_path, defaultRobotDescription(), finger_opening);
}

Model loadModel(const RobotDescription& description, double finger_opening) {
  return loadModel(description.urdf, description, finger_opening);
}

Model loadModel(const std::string& urdf_path, const RobotDescription& description, double finger_opening) {
  const std::string& path = urdf_path;
  const RobotDescription& d = description;
  const std::string xml = readFile(path);
  precheckXml(path, xml);
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(xml);
  if (!urdf) fail(path, "urdfdom could not build the robot tree (see its messages above)");

  Model model;
  model.urdf_path = path;
  model.finger_opening = std::max(0.0, finger_opening);

  // walk the arm chain: one revolute joint below each body
  urdf::LinkConstSharedPtr link = urdf->getLink(d.base_link);
  if (!link) fail(path, "no link named '" + d.base_link + "' (the chain's base, base_link of the robot description)");
  model.body_names[0] = link->name;
  model.inertias[0] = linkInertia(*link);
  model.frames.push_back(Frame{link->name, 0, Isometry::Identity()});
  addCapsules(path, *link, 0, Isometry::Identity(), d.capsule_prefix, model);
  for (int i = 0; i < kArmDofs; ++i) {
    urdf::JointConstSharedPtr joint;
    for (const auto& j : link->child_joints) {
      if (j->type == urdf::Joint::CONTINUOUS) {
        fail(path, "joint '" + j->name + "' is continuous: arm joints need position limits (type revolute)");
      }
      if (j->type != urdf::Joint::REVOLUTE) continue;
      if (joint) fail(path, "link '" + link->name + "' has more than one revolute child joint ('" + joint->name +
                            "', '" + j->name + "'): not a serial chain");
      joint = j;
    }
    if (!joint) {
      fail(path, "the arm chain is cut at link '" + link->name + "': no revolute joint below it (found " +
                 std::to_string(i) + " of 7 arm joints)");
    }
    const urdf::JointLimits& lim = *joint->limits;
    if (!(lim.lower < lim.upper)) fail(path, "joint '" + joint->name + "': limit lower must be < upper");
    if (!(lim.velocity > 0.0)) fail(path, "joint '" + joint->name + "': limit velocity must be > 0");
    if (!(lim.effort > 0.0)) fail(path, "joint '" + joint->name + "': limit effort must be > 0");
    const Vector3 axis(joint->axis.x, joint->axis.y, joint->axis.z);
    if (!(axis.norm() > 0.5)) fail(path, "joint '" + joint->name + "': axis is zero");

    link = urdf->getLink(joint->child_link_name);
    if (!link) fail(path, "joint '" + joint->name + "' names a missing child link '" + joint->child_link_name + "'");
    if (!link->inertial) fail(path, "link '" + link->name + "' has no <inertial>: every arm link needs mass properties");

    model.joint_names[i] = joint->name;
    model.joint_placements[i] = toIsometry(joint->parent_to_joint_origin_transform);
    model.joint_axes[i] = axis.normalized();
    model.q_min[i] = lim.lower;
    model.q_max[i] = lim.upper;
    model.v_max[i] = lim.velocity;
    model.tau_max[i] = lim.effort;
    model.a_max[i] = d.acceleration_limits[i];
    model.body_names[i + 1] = link->name;
    model.inertias[i + 1] = linkInertia(*link);
    model.frames.push_back(Frame{link->name, i + 1, Isometry::Identity()});
    addCapsules(path, *link, i + 1, Isometry::Identity(), d.capsule_prefix, model);
  }

  // hand, sensor, tcp and fingers are rigidly merged into body 7
  double finger_max = 0.0;
  Inertia body7 = model.inertias[kArmDofs];
  Inertia tool;  // body-7 frame until the sensor frame is known
  mergeSubtree(path, *urdf, *link, Isometry::Identity(), d.capsule_prefix, model, body7, finger_max, d.hand_link,
               tool, false);
  model.inertias[kArmDofs] = body7;
  if (finger_max > 0.0) {
    model.finger_max_opening = finger_max;
    model.finger_opening = std::min(model.finger_opening, finger_max);
  }

  // short aliases the controller uses
  for (const auto& [alias, link_name] : {std::pair<const char*, const std::string&>{"hand", d.hand_link},
                                         {"tcp", d.tcp_link},
                                         {"ft_sensor", d.ft_sensor_link}}) {
    if (!model.hasFrame(link_name)) {
      fail(path, "no link '" + link_name + "' fixed below '" + model.body_names[kArmDofs] + "' (needed for the '" +
                     alias + "' frame)");
    }
    Frame f = model.frames[model.frameId(link_name)];
    f.name = alias;
    model.frames.push_back(f);
  }
  // the tool's mass properties in the sensor frame (the sensor sits above the hand link)
  model.tool = transformInertia(tool, model.frames[model.frameId("ft_sensor")].placement.inverse());
  assignCapsuleRoles(path, d, model);
  assignLinkGroups(path, d, model);
  return model;
}

}  // namespace handover::control
