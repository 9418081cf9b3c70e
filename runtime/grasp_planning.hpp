// The grasp planner of the handover cycle: grasp selection and upright
// placement (control/grasp) on the robot's own model, fed by perception and
// read by the state machine (fsm::TrackingPlan in its input, and
// fsm::PlannerInterface for the placements a carrying state asks for, answered
// in HandoverCycle::plan).
//
// Take: while the person holds the object, each new object sample re-selects
// among the grasps the object admits (declared grasps, every turn about a
// free axis, the gripper's half-turn twins) the one the arm reaches best,
// avoiding the person's forearm, upper arm and trunk (no configuration nearer
// them than the collision constraints keep the arm: PersonKeeps), the hand
// where the fingers work kept clear of the palm and the arm's links, and the
// whole gripper in front of the object itself where the arm lines up (its
// pre-grasp: heldObjectObstacle).
// Give: while the robot holds the object, each new hand sample re-selects the
// presentation: the declared TCP-in-hand frame turned about the hand's z axis
// (the receiver takes the object at any turn about the vertical), upright or
// tilted by config.presentation_tilt in any direction (upright preferred by
// config.declared_preference), no twins (the held object would turn with the
// gripper), scored against the receiver's arm, none ruled out by it (the
// receiver comes to the object: presentationSelectionConfig).
//
// Frames: world; offsets in the observed frame (object or hand). Units: m, rad.
// Real-time: the constructor allocates; update() and uprightPlacement() do
// not, but cost 0.1-1 ms (IK solves): run them at the sensor rate or when a
// phase starts, outside the 1 ms control step (HandoverCycle::plan).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "control/collision/collision_config.hpp"
#include "control/collision/collision_model.hpp"
#include "control/grasp/grasp_selector.hpp"
#include "fsm/handover/grasp_plan.hpp"
#include "interfaces/object_shape.hpp"
#include "perception/perception_estimator.hpp"

namespace handover::runtime {

/// How far the collision constraints keep the arm's capsules and the
/// gripper's (palm and fingers) from each part of the person while the gripper
/// does not share the object with their hand (arm, gripper) and while it does
/// (arm_sharing, gripper_sharing: a take's grasp) (m: margin, sensing budget and
/// sDist of the pairs; personKeeps). The selector does not plan a
/// configuration nearer than that (control::grasp::personBodyClearance).
struct PersonKeeps {
  struct Keep {
    double arm = 0.0, gripper = 0.0;
    double arm_sharing = -1.0, gripper_sharing = -1.0;  ///< negative: as apart
  };
  Keep hand, forearm, upper_arm, trunk;
  Keep object;  ///< from the object the person holds out (the gripper lines up in front of it)
};

/// The largest clearance the `always` and `apart` pair rules keep between
/// each class of robot capsule and each part of the person, and the object
/// in their hand.
PersonKeeps personKeeps(const control::CollisionModel& model);

/// Where a receiver pulls a presented object (world, unit, horizontal): back
/// toward their shoulder, as people take an object to their body; zero when
/// the shoulder is straight above the hand. The give's presentation keeps the open
/// gripper out of that way (GraspSelector::setPullDirection).
control::Vector3 receiverPull(const perception::HumanEstimate& person);

struct GraspPlanningSettings {
  control::grasp::GraspSelectionConfig config;        ///< config/grasp_selection.yaml
  std::vector<control::grasp::GraspSpec> object_grasps;  ///< what the object admits (at least one)
  control::Isometry presentation = control::Isometry::Identity();  ///< declared TCP pose in the receiver's hand frame
  control::Vector3 presentation_pivot = control::Vector3::Zero();   ///< m, the object's centre there (the tilt's pivot)
  /// The give's grasp on the object (TCP in the object frame) and the object's
  /// shape: a presentation may also put the receiver's hand on the part of the
  /// object away from the gripper (presentationSpecs). Unknown shape: not.
  control::Isometry held_grasp = control::Isometry::Identity();
  io::ObjectShape object_shape;
  double forearm_length = 0.27, upper_arm_length = 0.33;  ///< m, the person's arm capsules
  double forearm_radius = 0.045, upper_arm_radius = 0.055;  ///< m
  /// m, a sphere around the grip point: a receiver's reach to a placement
  /// (uprightPlacement), and a take's holding hand when no hand box is given
  double hand_radius = 0.05;
  /// The hand box of the collision model (a take: the hand that holds the
  /// object, where only the fingers may go; a give: the presentation's gripper
  /// keeps from it what the constraints keep): centre and axes in the hand
  /// frame, half edges (m).
  control::Isometry hand_box = control::Isometry::Identity();
  control::Vector3 hand_box_half_extents = control::Vector3::Zero();
  /// The person's trunk (torso, head, the arm that does not hand) as capsules
  /// in the torso frame (trunkObstacles); empty when the stand is not declared.
  /// At most kMaxTrunkObstacles.
  std::vector<control::grasp::ObstacleCapsule> trunk;
  PersonKeeps keeps;  ///< what the collision constraints keep from the person (zero: only no overlap)
};

/// The give's presentations (TCP poses in the receiver's hand frame, with
/// free turns about the hand's z): the declared one upright and tilted by
/// config.presentation_tilt about the hand's x and y through the object's
/// centre; and each of these with the object moved so that the hand's grip
/// point lies on its free part, halfway from its centre to its surface on the
/// side away from the grasp (an object held near one end: the declared seat
/// put a bottle held 8 cm below its centre with the gripper inside the
/// receiver's hand, and the approach stopped 6 cm short until the give timed
/// out). Not for a grasp within 2 cm of the object's centre, nor an unknown shape.
std::vector<control::grasp::GraspSpec> presentationSpecs(const GraspPlanningSettings& settings);

/// At most this many trunk capsules (GraspPlanningSettings::trunk).
constexpr int kMaxTrunkObstacles = 4;

/// The object the person holds out as a selector obstacle (held_object, with
/// `keep` from it): a shape inscribed in it (a box; a sphere; a cylinder as
/// the capsule of its radius whose caps end at its flat faces, or, flatter
/// than it is wide, as the square box inscribed in it), so a pre-grasp is
/// refused only where the gripper surely meets the object. World frame;
/// `pose` the object frame (interfaces/object_shape.hpp). An unknown shape
/// gives an obstacle of radius 0 at its centre.
control::grasp::ObstacleCapsule heldObjectObstacle(const io::ObjectShape& shape, const control::Isometry& pose,
                                                   const PersonKeeps::Keep& keep);

/// The hand that holds the object out (a take) as a selector obstacle, where
/// only the fingers may go (gripper_works_here, with the hand's keeps): the
/// collision model's hand box (settings.hand_box, hand_box_half_extents) at
/// `hand` (the grip point, world), or a sphere of hand_radius when no box is
/// given. The sphere reached 3 cm past the palm's faces (and fell short of its
/// corners): it ruled out every grasp of balls and boxes held low, by 0.3-8 mm
/// (g1101_00613, g1109_00061), and the arm stalled at the declared grasp until
/// the person gave up.
control::grasp::ObstacleCapsule holdingHandObstacle(const GraspPlanningSettings& settings, const control::Isometry& hand);

/// The trunk of the collision model (a torso box, a head sphere, the free
/// arm's capsule; legs under the table are left out) as selector capsules in
/// the torso frame (floor under the body centre, x forward): the torso box as
/// two vertical capsules side by side whose stadium section fits the box's
/// and whose caps reach its top and bottom.
std::vector<control::grasp::ObstacleCapsule> trunkObstacles(const control::PersonTrunk& trunk,
                                                            double free_arm_radius);

class GraspPlanning : public fsm::PlannerInterface {
 public:
  /// Throws std::invalid_argument without object grasps; `model` must outlive it.
  GraspPlanning(const control::Model& model, const GraspPlanningSettings& settings);

  /// Re-selects on a new sample (take: the object while the person holds
  /// it; give: the hand while the robot holds the object); q: the arm now;
  /// torso: where the person's trunk stands (world), null when unknown.
  void update(const perception::PerceptionEstimate& estimate, const control::Vector7& q, bool robot_holds,
              const control::Isometry* torso = nullptr);
  /// Forgets both choices (a new object, a new run).
  void reset();
  /// Keeps the object's choice (take) while it stays reachable
  /// (GraspSelector::holdChoice). Real-time safe.
  void holdObjectChoice(bool on) { object_.holdChoice(on); }

  const fsm::TrackingPlan& objectPlan() const { return object_plan_; }
  const fsm::TrackingPlan& handPlan() const { return hand_plan_; }
  const control::grasp::GraspSelector& objectSelector() const { return object_; }

  /// With receiver_stop > 0 the placement is scored against the person as
  /// last seen (arm, trunk) and against their reach to it: a capsule of the
  /// hand's radius from their shoulder to where the hand stops, receiver_stop
  /// short of the object's centre, so the arm waits beside or behind the
  /// object as seen from them, not across their way to it.
  fsm::ArmPlacement uprightPlacement(const control::Isometry& object_in_tcp, const control::Vector3& up_axis,
                                     const control::Vector3& object_position, const control::Vector7& q_now,
                                     double receiver_stop) override;

 private:
  static void copyChoice(const control::grasp::GraspChoice& c, fsm::TrackingPlan& plan);
  /// Fills obstacles_ with the person's arm, their hand where it holds the
  /// object (holding_hand: a take; otherwise the hand box, keep-only, when
  /// settings give one) and their trunk (torso given); returns their number.
  int personObstacles(const perception::HumanEstimate& human, bool holding_hand, const control::Isometry* torso);
  /// How many of personObstacles' last ones are the trunk (torso given).
  int trunkObstacles(const control::Isometry* torso) const;

  const control::Model& model_;
  GraspPlanningSettings settings_;
  control::grasp::GraspSelector object_;
  control::grasp::GraspSelector hand_;
  fsm::TrackingPlan object_plan_, hand_plan_;
  double object_stamp_ = -1.0, hand_stamp_ = -1.0;
  /// The person as last seen (for the carries that wait for a receiver).
  std::optional<perception::HumanEstimate> last_person_;
  std::optional<control::Isometry> last_torso_;
  /// The person's arm, hand, trunk and reach (uprightPlacement), the held object (take).
  std::array<control::grasp::ObstacleCapsule, 5 + kMaxTrunkObstacles> obstacles_;
};

/// The presentation selector's options: no twins (a held object turns with the
/// gripper), no pre-grasp standoff (the object comes straight to the hand).
control::grasp::GraspSelectionConfig presentationSelectionConfig(control::grasp::GraspSelectionConfig config);

}  // namespace handover::runtime
