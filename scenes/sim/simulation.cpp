#include "scenes/sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

#include <mujoco/mujoco.h>

#include "config/input_error.hpp"
#include "control/controller_config.hpp"
#include "control/model/model.hpp"
#include "control/model/robot_description.hpp"
#include "scenes/sim/mujoco_messages.hpp"
#include "scenes/sim/scene_builder.hpp"

namespace handover::sim {
namespace {

constexpr double kMaxFingerTravel = 0.04;  // m per finger
constexpr double kMaxGraspForce = 140.0;   // N, datasheet peak
// VFS name of the generated scene; loaded as if it sat next to the template,
// so <include file="panda.xml"/> still resolves in the template's folder.
constexpr const char* kGeneratedName = "handover_scene.generated.xml";

std::string folderOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

std::string trimmed(const char* text) {
  std::string t(text);
  while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
  return t;
}

bool finite(const Eigen::Isometry3d& x) { return x.matrix().allFinite(); }

Eigen::Isometry3d poseFrom(const mjtNum* pos, const mjtNum* quat_wxyz) {
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  x.translation() = Eigen::Vector3d(pos[0], pos[1], pos[2]);
  x.linear() = Eigen::Quaterniond(quat_wxyz[0], quat_wxyz[1], quat_wxyz[2], quat_wxyz[3])
                   .normalized()
                   .toRotationMatrix();
  return x;
}

void writePose(const Eigen::Isometry3d& x, mjtNum* pos, mjtNum* quat_wxyz) {
  const Eigen::Quaterniond q(x.linear());
  for (int i = 0; i < 3; ++i) pos[i] = x.translation()[i];
  quat_wxyz[0] = q.w();
  quat_wxyz[1] = q.x();
  quat_wxyz[2] = q.y();
  quat_wxyz[3] = q.z();
}

}  // namespace

Simulation::Simulation() = default;
Simulation::~Simulation() { release(); }

void Simulation::release() {
  if (d_) mj_deleteData(d_);
  if (m_) mj_deleteModel(m_);
  d_ = nullptr;
  m_ = nullptr;
}

void Simulation::load(const SimOptions& options_in) {
  SimOptions options = options_in;
  if (options.scene_path.empty()) options.scene_path = defaultScenePath();
  const std::string& path = options.scene_path;

  // the arm's names from the robot description (its URDF's chain), the ready
  // posture from the controller's config: the simulator names no robot itself
  const control::RobotDescription description = options.robot_description.empty()
                                                    ? control::defaultRobotDescription()
                                                    : control::loadRobotDescription(options.robot_description);
  RobotNames robot;
  {
    const control::Model chain = control::loadModel(description, control::Model{}.finger_opening);
    robot.description = description.file;
    for (int j = 0; j < 7; ++j) robot.arm_joints[j] = chain.joint_names[j];
    robot.base = description.base_link;
    robot.hand = description.hand_link;
    robot.fingers = description.finger_links;
  }
  const Eigen::Matrix<double, 7, 1> ready =
      control::loadControllerConfig(control::defaultControllerConfigPath()).posture.target;

  installMujocoMessageHandlers();  // MuJoCo's warnings stay out of the user's folder
  std::ifstream in(path);
  if (!in) throw InputError("scene file " + path + ": cannot be opened (missing or unreadable)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string xml;
  try {
    xml = buildSceneXml(buffer.str(), options, path);
  } catch (const InputError&) {
    // a template that MuJoCo itself rejects deserves MuJoCo's message
    char error[1024] = "";
    if (mjModel* raw = mj_loadXML(path.c_str(), nullptr, error, sizeof(error))) {
      mj_deleteModel(raw);
      throw;
    }
    throw InputError("scene file " + path + ": MuJoCo cannot load it: " + trimmed(error));
  }

  // compile from memory (MuJoCo's VFS), named as a file in the template's folder
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), kGeneratedName, static_cast<int>(xml.size())) != 0) {
    throw InputError("scene file " + path + ": cannot stage the generated MJCF");
  }
  std::memcpy(vfs->filedata[vfs->nfile - 1], xml.data(), xml.size());
  char error[1024] = "";
  const std::string virtual_path = folderOf(path) + "/" + kGeneratedName;
  mjModel* m = mj_loadXML(virtual_path.c_str(), vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (!m) throw InputError("scene file " + path + ": MuJoCo cannot load it: " + trimmed(error));

  release();
  m_ = m;
  d_ = mj_makeData(m_);
  options_ = options;
  try {
    resolveNames(path, robot);
  } catch (...) {
    release();
    throw;
  }
  reset(ready, kMaxFingerTravel * 2);
}

void Simulation::resolveNames(const std::string& source, const RobotNames& robot) {
  auto id = [&](int type, const std::string& name, const char* what) {
    const int i = mj_name2id(m_, type, name.c_str());
    if (i < 0) {
      throw InputError("scene file " + source + ": no " + what + " named '" + name +
                       "' (simulator contract, DEVELOPERS.md)");
    }
    return i;
  };
  // a robot name the scene must hold as well (the robot description's)
  auto robotId = [&](int type, const std::string& name, const char* what) {
    const int i = mj_name2id(m_, type, name.c_str());
    if (i < 0) {
      throw InputError("scene file " + source + ": no " + what + " named '" + name + "' (named by the robot description " +
                       robot.description + ")");
    }
    return i;
  };
  // each actuator must drive the joint the description puts in its place
  auto drives = [&](int actuator, int joint) {
    if (m_->actuator_trntype[actuator] != mjTRN_JOINT || m_->actuator_trnid[2 * actuator] != joint) {
      throw InputError("scene file " + source + ": actuator '" + mj_id2name(m_, mjOBJ_ACTUATOR, actuator) +
                       "' must drive joint '" + mj_id2name(m_, mjOBJ_JOINT, joint) + "'");
    }
  };
  for (int j = 0; j < 7; ++j) {
    const int joint = robotId(mjOBJ_JOINT, robot.arm_joints[j], "joint");
    if (m_->jnt_type[joint] != mjJNT_HINGE) {
      throw InputError("scene file " + source + ": joint '" + robot.arm_joints[j] + "' must be a hinge (arm joint " +
                       std::to_string(j + 1) + ")");
    }
    arm_qpos_[j] = m_->jnt_qposadr[joint];
    arm_dof_[j] = m_->jnt_dofadr[joint];
    arm_act_[j] = id(mjOBJ_ACTUATOR, "act_joint" + std::to_string(j + 1), "actuator");
    drives(arm_act_[j], joint);
  }
  int finger_body[2];
  for (int f = 0; f < 2; ++f) {
    // the finger link's one slide joint
    finger_body[f] = robotId(mjOBJ_BODY, robot.fingers[f], "body");
    const int joint = m_->body_jntadr[finger_body[f]];
    if (m_->body_jntnum[finger_body[f]] != 1 || m_->jnt_type[joint] != mjJNT_SLIDE) {
      throw InputError("scene file " + source + ": body '" + robot.fingers[f] + "' must have one slide joint (a finger)");
    }
    finger_qpos_[f] = m_->jnt_qposadr[joint];
    finger_dof_[f] = m_->jnt_dofadr[joint];
    finger_act_[f] = id(mjOBJ_ACTUATOR, f == 0 ? "act_finger_left" : "act_finger_right", "actuator");
    drives(finger_act_[f], joint);
    m_->actuator_forcelimited[finger_act_[f]] = 1;  // applyCommand sets the range
  }
  ft_force_adr_ = m_->sensor_adr[id(mjOBJ_SENSOR, "ft_force", "sensor")];
  ft_torque_adr_ = m_->sensor_adr[id(mjOBJ_SENSOR, "ft_torque", "sensor")];
  ft_site_ = id(mjOBJ_SITE, "ft_sensor", "site");
  tcp_site_ = id(mjOBJ_SITE, "tcp", "site");
  hand_body_ = robotId(mjOBJ_BODY, robot.hand, "body");

  object_body_ = id(mjOBJ_BODY, "object", "body");
  const int object_joint = m_->body_jntadr[object_body_];
  if (object_joint < 0 || m_->jnt_type[object_joint] != mjJNT_FREE) {
    throw InputError("scene file " + source + ": body 'object' must have a free joint");
  }
  object_qpos_ = m_->jnt_qposadr[object_joint];
  object_dof_ = m_->jnt_dofadr[object_joint];

  weld_ = id(mjOBJ_EQUALITY, "object_weld", "equality");
  human_hand_body_ = id(mjOBJ_BODY, "human_hand", "body");
  if (m_->eq_type[weld_] != mjEQ_WELD || m_->eq_obj1id[weld_] != human_hand_body_ ||
      m_->eq_obj2id[weld_] != object_body_) {
    throw InputError("scene file " + source + ": 'object_weld' must be a weld with body1=human_hand body2=object");
  }
  std::copy(m_->eq_data + mjNEQDATA * weld_, m_->eq_data + mjNEQDATA * (weld_ + 1), weld_data0_.begin());

  auto mocap = [&](const char* name) {
    const int b = id(mjOBJ_BODY, name, "body");
    if (m_->body_mocapid[b] < 0) throw InputError("scene file " + source + ": body '" + name + "' must be mocap");
    return m_->body_mocapid[b];
  };
  mocap_hand_ = mocap("human_hand");
  mocap_forearm_ = mocap("human_forearm");
  mocap_upper_arm_ = mocap("human_upper_arm");
  mocap_torso_ = mocap("human_torso");
  forearm_geom_ = id(mjOBJ_GEOM, "human_forearm_geom", "geom");
  upper_arm_geom_ = id(mjOBJ_GEOM, "human_upper_arm_geom", "geom");
  for (int g : {forearm_geom_, upper_arm_geom_}) {
    if (m_->geom_type[g] != mjGEOM_CAPSULE) {
      throw InputError("scene file " + source + ": geom '" + mj_id2name(m_, mjOBJ_GEOM, g) + "' must be a capsule");
    }
  }

  // what each geom is, for the contact report
  const int robot_root = m_->body_rootid[robotId(mjOBJ_BODY, robot.base, "body")];
  const int left = finger_body[0];
  const int right = finger_body[1];
  const int person[] = {human_hand_body_, id(mjOBJ_BODY, "human_forearm", "body"),
                        id(mjOBJ_BODY, "human_upper_arm", "body"), id(mjOBJ_BODY, "human_torso", "body")};
  const int table = id(mjOBJ_GEOM, "table", "geom");
  const int floor = id(mjOBJ_GEOM, "floor", "geom");
  geom_role_.assign(m_->ngeom, kOther);
  for (int g = 0; g < m_->ngeom; ++g) {
    const int b = m_->geom_bodyid[g];
    const char* name = mj_id2name(m_, mjOBJ_GEOM, g);
    if (b == left) geom_role_[g] = kLeftFinger;
    else if (b == right) geom_role_[g] = kRightFinger;
    else if (b != 0 && m_->body_rootid[b] == robot_root) geom_role_[g] = kRobot;
    else if (std::find(std::begin(person), std::end(person), b) != std::end(person)) geom_role_[g] = kPerson;
    else if (b == object_body_) geom_role_[g] = kObject;
    else if (g == table || (name && std::strncmp(name, "table_", 6) == 0)) geom_role_[g] = kTable;
    else if (g == floor) geom_role_[g] = kFloor;
  }
}

void Simulation::reset(const Eigen::Matrix<double, 7, 1>& q0, double finger_width,
                       const std::optional<Eigen::Isometry3d>& object_in_tcp) {
  if (!m_) throw InputError("Simulation::reset: no scene loaded");
  if (!q0.allFinite() || !std::isfinite(finger_width) || (object_in_tcp && !finite(*object_in_tcp))) {
    throw InputError("Simulation::reset: non-finite start configuration");
  }
  mj_resetData(m_, d_);  // also puts the mocap bodies back at their scene poses
  diverged_at_ = -1.0;
  divergence_kind_ = -1;
  divergence_dof_ = -1;
  clearMujocoWarning();
  m_->eq_active[weld_] = 0;
  std::copy(weld_data0_.begin(), weld_data0_.end(), m_->eq_data + mjNEQDATA * weld_);

  for (int j = 0; j < 7; ++j) d_->qpos[arm_qpos_[j]] = q0[j];
  const double half = std::clamp(0.5 * finger_width, 0.0, kMaxFingerTravel);
  for (int f = 0; f < 2; ++f) {
    d_->qpos[finger_qpos_[f]] = half;
    d_->ctrl[finger_act_[f]] = half;
  }
  ArmCommand open;
  open.gripper_width = 2 * half;
  open.tau.setZero();
  applyCommand(open);

  mj_kinematics(m_, d_);
  if (object_in_tcp) setObjectQpos(tcpPose() * *object_in_tcp, Vector6::Zero());
  mj_forward(m_, d_);
}

void Simulation::step() {
  const double t0 = d_->time;
  for (int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC}) d_->warning[w].number = 0;
  mj_step(m_, d_);
  if (diverged()) return;
  // MuJoCo resets the world when the state turns bad: the counters say why,
  // the clock going back says that it happened
  for (int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC}) {
    if (d_->warning[w].number > 0) {
      divergence_kind_ = w;
      divergence_dof_ = d_->warning[w].lastinfo;
      diverged_at_ = t0;
      return;
    }
  }
  if (!(d_->time > t0)) diverged_at_ = t0;
}

std::string Simulation::divergenceMessage() const {
  if (!diverged()) return "";
  const char* what = divergence_kind_ == mjWARN_BADQPOS   ? "position"
                     : divergence_kind_ == mjWARN_BADQVEL ? "velocity"
                     : divergence_kind_ == mjWARN_BADQACC ? "acceleration"
                                                          : "state";
  std::ostringstream os;
  os << "the simulation diverged at t = " << diverged_at_ << " s (a NaN, infinite or huge " << what;
  if (divergence_dof_ >= 0) os << " at MuJoCo dof " << divergence_dof_;
  os << "; MuJoCo reset the world)";
  std::string warning = trimmed(lastMujocoWarning());
  while (!warning.empty() && (warning.back() == '.' || warning.back() == ' ')) warning.pop_back();
  if (!warning.empty()) os << ": MuJoCo: " << warning;
  os << "; look for absurd inputs (tracker values, scenario poses or settings)";
  return os.str();
}

ArmState Simulation::armState() const {
  ArmState s;
  s.time = d_->time;
  for (int j = 0; j < 7; ++j) {
    s.q[j] = d_->qpos[arm_qpos_[j]];
    s.qd[j] = d_->qvel[arm_dof_[j]];
    s.tau_measured[j] = d_->actuator_force[arm_act_[j]];
  }
  s.finger_width = d_->qpos[finger_qpos_[0]] + d_->qpos[finger_qpos_[1]];
  // MuJoCo reports the force the flange exerts on the hand (the subtree's
  // support); the hand exerts the opposite on the flange.
  for (int i = 0; i < 3; ++i) {
    s.wrench[i] = -d_->sensordata[ft_force_adr_ + i];
    s.wrench[3 + i] = -d_->sensordata[ft_torque_adr_ + i];
  }
  return s;
}

void Simulation::applyCommand(const ArmCommand& command) {
  for (int j = 0; j < 7; ++j) {
    const int a = arm_act_[j];
    double tau = std::isfinite(command.tau[j]) ? command.tau[j] : 0.0;
    if (m_->actuator_ctrllimited[a]) {
      tau = std::clamp(tau, m_->actuator_ctrlrange[2 * a], m_->actuator_ctrlrange[2 * a + 1]);
    }
    d_->ctrl[a] = tau;
  }
  const double width = std::isfinite(command.gripper_width) ? command.gripper_width : 0.0;
  const double half = std::clamp(0.5 * width, 0.0, kMaxFingerTravel);
  const bool force_ok = std::isfinite(command.gripper_force);
  const double force = std::clamp(force_ok ? command.gripper_force : 0.0, 0.0, kMaxGraspForce);
  for (int f = 0; f < 2; ++f) {
    const int a = finger_act_[f];
    if (std::isfinite(command.gripper_width)) d_->ctrl[a] = half;
    if (force_ok) {
      m_->actuator_forcerange[2 * a] = -force;
      m_->actuator_forcerange[2 * a + 1] = force;
    }
  }
}

bool Simulation::setHumanPoses(const HumanBodyPoses& p) {
  if (!finite(p.hand) || !finite(p.forearm) || !finite(p.upper_arm) || !finite(p.torso) ||
      !std::isfinite(p.forearm_length) || !std::isfinite(p.upper_arm_length) || p.forearm_length <= 0.0 ||
      p.upper_arm_length <= 0.0) {
    return false;
  }
  writePose(p.hand, d_->mocap_pos + 3 * mocap_hand_, d_->mocap_quat + 4 * mocap_hand_);
  writePose(p.forearm, d_->mocap_pos + 3 * mocap_forearm_, d_->mocap_quat + 4 * mocap_forearm_);
  writePose(p.upper_arm, d_->mocap_pos + 3 * mocap_upper_arm_, d_->mocap_quat + 4 * mocap_upper_arm_);
  writePose(p.torso, d_->mocap_pos + 3 * mocap_torso_, d_->mocap_quat + 4 * mocap_torso_);
  // capsule from the segment origin along its z: centre at L/2, half-length L/2
  auto resize = [&](int g, double length) {
    m_->geom_size[3 * g + 1] = 0.5 * length;
    m_->geom_pos[3 * g + 2] = 0.5 * length;
    m_->geom_rbound[g] = m_->geom_size[3 * g] + 0.5 * length;
  };
  resize(forearm_geom_, p.forearm_length);
  resize(upper_arm_geom_, p.upper_arm_length);
  return true;
}

void Simulation::syncWeldReference() {
  // current poses, read from the state itself (xpos lags one step after mj_step)
  const Eigen::Isometry3d hand = humanHandPose();
  const Eigen::Isometry3d obj = poseFrom(d_->qpos + object_qpos_, d_->qpos + object_qpos_ + 3);
  setObjectGrip(hand.inverse() * obj);
}

void Simulation::setObjectGrip(const Eigen::Isometry3d& rel) {
  if (!finite(rel)) return;
  const Eigen::Quaterniond q(rel.linear());
  mjtNum* data = m_->eq_data + mjNEQDATA * weld_;
  // MuJoCo 2.2.2 weld: anchor (in body2) 0..2, relpos (body2 in body1) 3..5, relquat 6..9
  data[0] = data[1] = data[2] = 0.0;
  for (int i = 0; i < 3; ++i) data[3 + i] = rel.translation()[i];
  data[6] = q.w();
  data[7] = q.x();
  data[8] = q.y();
  data[9] = q.z();
}

void Simulation::setObjectWeld(bool on) {
  if (on && !m_->eq_active[weld_]) syncWeldReference();
  m_->eq_active[weld_] = on ? 1 : 0;
}

bool Simulation::objectWelded() const { return m_->eq_active[weld_] != 0; }

void Simulation::setObjectQpos(const Eigen::Isometry3d& pose, const Vector6& velocity) {
  writePose(pose, d_->qpos + object_qpos_, d_->qpos + object_qpos_ + 3);
  // free joint: linear velocity in world axes, angular velocity in the body frame
  const Eigen::Vector3d w_local = pose.linear().transpose() * velocity.tail<3>();
  for (int i = 0; i < 3; ++i) {
    d_->qvel[object_dof_ + i] = velocity[i];
    d_->qvel[object_dof_ + 3 + i] = w_local[i];
  }
}

void Simulation::placeObject(const Eigen::Isometry3d& pose, const Vector6& velocity) {
  if (!finite(pose) || !velocity.allFinite()) return;
  setObjectQpos(pose, velocity);
  if (m_->eq_active[weld_]) syncWeldReference();  // a placed object stays where it was put
  // forward, not only kinematics: the contact list must describe the object
  // where it now is, not where it was (the scene starts it on the table)
  mj_forward(m_, d_);
}

ContactReport Simulation::contacts() const {
  ContactReport r;
  for (int i = 0; i < d_->ncon; ++i) {
    const mjContact& c = d_->contact[i];
    const unsigned char a = geom_role_[c.geom1], b = geom_role_[c.geom2];
    auto pair = [&](unsigned char x, unsigned char y) { return (a == x && b == y) || (a == y && b == x); };
    auto robot = [](unsigned char x) { return x == kRobot || x == kLeftFinger || x == kRightFinger; };
    if ((robot(a) && b == kPerson) || (robot(b) && a == kPerson)) ++r.robot_human;
    if (pair(kLeftFinger, kObject)) r.left_finger_on_object = true;
    if (pair(kRightFinger, kObject)) r.right_finger_on_object = true;
    if (pair(kObject, kTable)) r.object_on_table = true;
    if (pair(kObject, kFloor)) r.object_on_floor = true;
  }
  r.object_welded_to_hand = objectWelded();
  return r;
}

PersonClearance Simulation::personClearance(double cap) const {
  PersonClearance out{cap, cap};
  mjContact con[mjMAXCONPAIR];
  auto robot = [](unsigned char x) { return x == kRobot || x == kLeftFinger || x == kRightFinger; };
  for (int g1 = 0; g1 < m_->ngeom; ++g1) {
    if (!robot(geom_role_[g1]) || !(m_->geom_contype[g1] & 1)) continue;  // visual geoms do not count
    const bool finger = geom_role_[g1] != kRobot;
    for (int g2 = 0; g2 < m_->ngeom; ++g2) {
      if (geom_role_[g2] != kPerson) continue;
      // bounding spheres: nothing closer than cap can hide beyond them
      const mjtNum* p1 = d_->geom_xpos + 3 * g1;
      const mjtNum* p2 = d_->geom_xpos + 3 * g2;
      const double centre = std::sqrt((p1[0] - p2[0]) * (p1[0] - p2[0]) + (p1[1] - p2[1]) * (p1[1] - p2[1]) +
                                      (p1[2] - p2[2]) * (p1[2] - p2[2]));
      if (centre - m_->geom_rbound[g1] - m_->geom_rbound[g2] >= cap) continue;
      // MuJoCo's narrow phase wants the pair in type order; it reports every
      // point closer than the margin, so a margin of `cap` yields the distance
      int a = g1, b = g2;
      if (m_->geom_type[a] > m_->geom_type[b]) std::swap(a, b);
      const mjfCollision collide = mjCOLLISIONFUNC[m_->geom_type[a]][m_->geom_type[b]];
      if (!collide) continue;
      // MuJoCo 2.2.2's box-box test is exact for overlaps but returns made-up
      // depths (down to -1 m) when asked for distances with a wide margin:
      // box pairs (the fingers against the hand or the trunk) give only
      // penetrations, as in MuJoCo's own contact list; the gripper's other
      // geoms bound how far the fingers are
      const bool box_box = m_->geom_type[a] == mjGEOM_BOX && m_->geom_type[b] == mjGEOM_BOX;
      const int n = collide(m_, d_, con, a, b, box_box ? 0.0 : cap);
      for (int i = 0; i < n; ++i) {
        out.all = std::min(out.all, static_cast<double>(con[i].dist));
        if (!finger) out.without_fingers = std::min(out.without_fingers, static_cast<double>(con[i].dist));
      }
    }
  }
  return out;
}

ObjectState Simulation::object() const {
  ObjectState s;
  s.pose = poseFrom(d_->qpos + object_qpos_, d_->qpos + object_qpos_ + 3);
  const Eigen::Vector3d w_local(d_->qvel[object_dof_ + 3], d_->qvel[object_dof_ + 4], d_->qvel[object_dof_ + 5]);
  s.velocity.head<3>() = Eigen::Vector3d(d_->qvel[object_dof_], d_->qvel[object_dof_ + 1], d_->qvel[object_dof_ + 2]);
  s.velocity.tail<3>() = s.pose.linear() * w_local;
  return s;
}

Eigen::Isometry3d Simulation::tcpPose() const {
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  const mjtNum* p = d_->site_xpos + 3 * tcp_site_;
  const mjtNum* R = d_->site_xmat + 9 * tcp_site_;  // row-major
  x.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) x.linear()(r, c) = R[3 * r + c];
  return x;
}

Eigen::Isometry3d Simulation::humanHandPose() const {
  return poseFrom(d_->mocap_pos + 3 * mocap_hand_, d_->mocap_quat + 4 * mocap_hand_);
}

double Simulation::time() const { return d_ ? d_->time : 0.0; }
double Simulation::timestep() const { return m_ ? m_->opt.timestep : 0.0; }
double Simulation::handMass() const { return m_->body_subtreemass[hand_body_]; }

}  // namespace handover::sim
