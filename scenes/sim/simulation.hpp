// The simulated world (MuJoCo 2.2.2): the Panda, the table, the person's
// kinematic bodies and the free object. The controller talks to it only
// through the plain structs of sim_io.hpp (state in, command out).
//
// Frames: world z up, robot base at the origin, table top z = 0, floor
// z = -0.75 (design notes section 1). Units SI. Quaternions are Eigen's.
//
// Real-time safety: load() allocates (model, data, name tables); after it,
// every other call is real-time safe (no allocation, no exceptions) except
// reset(), which allocates nothing but may throw InputError for bad input.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "interfaces/arm_driver.hpp"
#include "scenes/sim/sim_io.hpp"
#include "scenes/sim/sim_options.hpp"

struct mjModel_;
struct mjData_;

namespace handover::sim {

/// The simulated world; as an io::ArmDriver it is the arm the control cycle drives.
class Simulation : public io::ArmDriver {
 public:
  Simulation();
  ~Simulation() override;
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Builds the scene from options.scene_path (default scenes/handover_scene.xml),
  /// sized from the options (scene_builder.hpp), compiles it and resets to the
  /// ready posture (config/controller.yaml posture.target). The robot's
  /// names come from the robot description (options.robot_description,
  /// default config/robot.yaml): the arm joints are its URDF chain's, in
  /// chain order; the base, hand and finger bodies its base_link, frames.hand
  /// and gripper.fingers; the scene must hold them, and its actuators
  /// act_joint1..7, act_finger_left/right must drive those joints. Throws handover::InputError naming the file and quoting
  /// MuJoCo's error for a missing, unreadable or broken MJCF, or naming the
  /// element/option that is missing or invalid. Not real-time.
  void load(const SimOptions& options = {});
  bool loaded() const { return m_ != nullptr; }

  /// Arm at q0 (rad) at rest, fingers at `finger_width` (total opening, m,
  /// clamped to 0..0.08) with the finger targets there too, person back at the
  /// scene's start poses, weld off, time 0. With `object_in_tcp`, the object
  /// starts at that pose in the "tcp" frame (in the gripper), at rest;
  /// otherwise at its scene pose (on the table). Throws InputError for
  /// non-finite input. Allocates nothing.
  void reset(const Eigen::Matrix<double, 7, 1>& q0, double finger_width,
             const std::optional<Eigen::Isometry3d>& object_in_tcp = std::nullopt);

  /// One physics step of timestep() (1 ms). Real-time safe. When MuJoCo
  /// finds the state diverged (a NaN, infinite or huge position, velocity or
  /// acceleration: it warns and resets the whole world to the model's rest
  /// state, time 0), the step is marked: diverged() turns true and stays so
  /// until reset(). MuJoCo's warning is not printed and writes no
  /// MUJOCO_LOG.TXT (mujoco_messages.hpp).
  void step();
  /// Whether a step since the last reset() diverged (see step()). Real-time safe.
  bool diverged() const { return diverged_at_ >= 0.0; }
  /// What diverged and when, for the run's error message ("" while not
  /// diverged). Allocates: not real-time.
  std::string divergenceMessage() const;

  /// Joint state, finger width, applied torques and wrist wrench. The wrench
  /// is [force; torque] that the hand (with fingers and whatever they hold)
  /// exerts on the flange, in the "ft_sensor" frame, torque about the sensor
  /// origin: at rest with an empty hand, force = the hand's weight (pointing
  /// down in the world). Real-time safe.
  ArmState armState() const;

  /// Joint torques clamped to the actuators' ranges (87/12 N m); non-finite
  /// entries are replaced by 0. Finger targets = gripper_width / 2 each
  /// (clamped to 0..0.04 m), finger force limit = gripper_force (clamped to
  /// 0..140 N, per finger; a non-finite value keeps the previous limit).
  /// Real-time safe.
  void applyCommand(const ArmCommand& command);

  // io::ArmDriver: armState() and applyCommand(). Real-time safe.
  ArmState state() const override { return armState(); }
  void apply(const ArmCommand& command) override { applyCommand(command); }

  /// Moves the person's mocap bodies and resizes the forearm / upper-arm
  /// capsules to the given lengths (geom size, position and bounding radius
  /// together). Returns false and changes nothing if any pose or length is
  /// not finite or a length is not positive. Real-time safe.
  bool setHumanPoses(const HumanBodyPoses& poses);

  /// Switches the person's grip (weld human_hand -> object) on or off. On:
  /// the current relative pose becomes the weld's reference first, so the
  /// object does not jump. Real-time safe.
  void setObjectWeld(bool on);
  bool objectWelded() const;
  /// Sets where the grip holds the object: its pose in the hand frame (e.g.
  /// from a tracker that follows the object); the weld pulls it there.
  /// Non-finite input is ignored. Real-time safe.
  void setObjectGrip(const Eigen::Isometry3d& hand_T_object);

  /// Puts the object at `pose` (world) with `velocity` [linear; angular],
  /// world axes; while welded, the grip is re-taken at the new pose (no snap
  /// back). Non-finite input is ignored. Real-time safe.
  void placeObject(const Eigen::Isometry3d& pose, const Vector6& velocity = Vector6::Zero());

  /// Contacts found by the last step (or reset, or placeObject), i.e. at the
  /// state the last step started from (at most one step old). Real-time safe.
  ContactReport contacts() const;

  /// True robot-person clearance from MuJoCo's geometry (every robot geom
  /// with contype 1 against every person geom), at the state contacts()
  /// describes; distances above `cap` (m) read as `cap`. A penetration
  /// counts whether or not MuJoCo's contact list holds it. Box-box pairs
  /// (the finger boxes against the hand, torso and legs boxes) report only
  /// penetrations: MuJoCo 2.2.2's box-box distances are unreliable. For
  /// judges and tests. Real-time safe (a fixed contact buffer on the stack).
  PersonClearance personClearance(double cap = 0.5) const;

  /// Ground truth of the object. Real-time safe.
  ObjectState object() const;

  /// Ground truth world pose of the "tcp" site (as of the last step's start,
  /// like contacts()) and of the person's hand (current), for judges and
  /// tests; the controller uses its own kinematics. Real-time safe.
  Eigen::Isometry3d tcpPose() const;
  Eigen::Isometry3d humanHandPose() const;

  double time() const;      ///< s since reset
  double timestep() const;  ///< s (0.001)

  /// Mass of the bodies below the F/T sensor (hand + fingers), kg.
  double handMass() const;
  const SimOptions& options() const { return options_; }

  /// Read-only access for rendering and diagnostics. The controller never
  /// uses these (state in, command out).
  const mjModel_* mujocoModel() const { return m_; }
  const mjData_* mujocoData() const { return d_; }
  /// Non-const mjData for renderers whose API takes mjData* (mjv_updateScene
  /// only reads it). Do not change the state through it.
  mjData_* mujocoDataForRendering() { return d_; }

 private:
  enum GeomRole : unsigned char { kOther, kRobot, kLeftFinger, kRightFinger, kPerson, kObject, kTable, kFloor };
  /// The robot's names the scene must hold (from the robot description).
  struct RobotNames {
    std::string description;                  ///< the description file (messages)
    std::array<std::string, 7> arm_joints;    ///< chain order
    std::string base, hand;                   ///< bodies
    std::array<std::string, 2> fingers;       ///< left, right bodies
  };

  void release();
  void resolveNames(const std::string& source, const RobotNames& robot);
  void syncWeldReference();
  void setObjectQpos(const Eigen::Isometry3d& pose, const Vector6& velocity);

  SimOptions options_;
  mjModel_* m_ = nullptr;
  mjData_* d_ = nullptr;

  // ids and addresses resolved once at load
  std::array<int, 7> arm_qpos_{}, arm_dof_{}, arm_act_{};
  std::array<int, 2> finger_qpos_{}, finger_dof_{}, finger_act_{};
  int ft_force_adr_ = -1, ft_torque_adr_ = -1, ft_site_ = -1, tcp_site_ = -1;
  int hand_body_ = -1;  ///< the description's hand link
  int object_body_ = -1, object_qpos_ = -1, object_dof_ = -1;
  int weld_ = -1;
  int mocap_hand_ = -1, mocap_forearm_ = -1, mocap_upper_arm_ = -1, mocap_torso_ = -1;
  int human_hand_body_ = -1;
  int forearm_geom_ = -1, upper_arm_geom_ = -1;
  std::array<double, 11> weld_data0_{};  ///< eq_data as compiled (restored by reset)
  std::vector<unsigned char> geom_role_;   ///< GeomRole per geom
  double diverged_at_ = -1.0;              ///< s, time of the step that diverged (-1: none)
  int divergence_kind_ = -1;               ///< mjtWarning of it (mjWARN_BADQPOS/QVEL/QACC), -1 when unknown
  int divergence_dof_ = -1;                ///< MuJoCo's dof index in the warning
};

}  // namespace handover::sim
