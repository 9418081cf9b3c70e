// Settings of grasp selection and upright placement, from
// config/grasp_selection.yaml (strict: unknown keys and out-of-range values
// are InputErrors naming the file, key and line). Start-up only.
#pragma once

#include <string>
#include <vector>

#include "config/yaml_reader.hpp"
#include "control/grasp/grasp_candidates.hpp"
#include "control/grasp/grasp_score.hpp"
#include "control/grasp/inverse_kinematics.hpp"
#include "control/grasp/palm_fit.hpp"

namespace handover::control::grasp {

/// Upright stow / presentation search (upright_placement.hpp).
struct UprightOptions {
  double yaw_step = 30.0 * M_PI / 180.0;      ///< rad, spacing of the turns about world z
  double tilt_tolerance = 10.0 * M_PI / 180.0;///< rad, largest angle between the object's up axis and world z
  std::vector<Vector3> position_offsets{Vector3::Zero()};  ///< m, tried in order around the nominal position
};

struct GraspSelectionConfig {
  std::string frame = "tcp";          ///< model frame that meets the grasp frame
  IkOptions ik;
  std::vector<Vector7> seeds;         ///< rad, fixed IK seeds tried after the current q on a cold start
  CandidateOptions candidates;
  /// The gripper's palm: how deep a grasp can go (candidates.palm; palm_fit.hpp,
  /// applied by whoever builds the specs from the object's shape).
  PalmGeometry palm;
  ScoreWeights score;
  /// The table top (world z, m): a configuration whose arm capsules (link 2
  /// onward) dip below table_height + table_clearance is not reachable.
  double table_height = 0.0;
  double table_clearance = 0.02;
  double hysteresis = 0.15;           ///< score units another candidate must gain to replace the current choice
  /// The current choice stays reachable while its IK (grasp and pre-grasp)
  /// ends within this of the target; any other candidate must converge to
  /// the IK's own tolerance (ik). A target at the edge of the workspace (the
  /// arm nearly stretched) crosses the IK's tolerance back and forth with the
  /// sensor's noise: a top grasp's pre-grasp 0.4-2 mm out of reach flipped
  /// the choice to a grasp a quarter turn away and back, every few updates.
  struct {
    double position = 0.005;                   ///< m
    double orientation = 0.5 * M_PI / 180.0;   ///< rad
  } keep_tolerance;
  /// Score units added to the grasps the object declares over the families
  /// its shape allows (GraspSpec::preference; applied by whoever builds the specs).
  double declared_preference = 0.5;
  /// IK solves from one fixed seed spent per update on candidates without a
  /// warm start (unreachable so far, or lost), round-robin; bounds the cost of
  /// candidates that stay out of reach. 0 = every seed for every such
  /// candidate in every update. While no candidate has a solution yet, all
  /// seeds are tried regardless.
  int cold_solves_per_update = 2;
  /// Warm candidates (solved from their previous solution, so on the IK branch
  /// they were first found on) also solved from the current configuration, the
  /// better-scoring solution kept: the arm may since have moved onto another
  /// branch (a give's wrist turned the other way to wait), from which a
  /// candidate the old branch reaches badly is a short move. Per update,
  /// round-robin; 0 = every warm candidate in every update.
  int branch_solves_per_update = 2;
  UprightOptions upright;
  /// rad: besides upright, a give may present the object tilted this far
  /// (about a horizontal axis through its centre, in any direction): people
  /// hand over and take objects tilted like this, and above a high or far
  /// hand an upright object held from the top puts the wrist out of the
  /// arm's reach. 0 = upright only. The upright presentation keeps
  /// declared_preference.
  double presentation_tilt = 30.0 * M_PI / 180.0;
  /// Not a file key: reject candidates nearer the person's body than the
  /// obstacles' keeps (personBodyClearance < 0). Off for presentations
  /// (presentationSelectionConfig): the receiver's hand and arm come to the
  /// object, so where they are when it is chosen is not where they will be.
  bool reject_inside_keeps = true;
};

/// Reads and validates a config file (see config/grasp_selection.yaml for every key).
GraspSelectionConfig loadGraspSelectionConfig(const std::string& path);
/// Same from an already loaded document (tests, overrides).
GraspSelectionConfig graspSelectionConfigFrom(const YamlReader& root);

}  // namespace handover::control::grasp
