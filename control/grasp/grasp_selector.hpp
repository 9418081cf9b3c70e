// Continuous grasp selection: among the object's grasp candidates, the one
// the arm reaches best, with hysteresis so the choice does not flicker.
//
// Every update poses each candidate (and its pre-grasp) on the current object
// pose, solves IK for both, scores the grasp configuration (grasp_score.hpp;
// the margin and clearance terms take the worse of grasp and pre-grasp) and
// keeps the current choice unless another feasible candidate beats it by
// `hysteresis`, or the current one became unreachable. Reachability has its
// hysteresis too: a candidate becomes reachable when its IK converges to the
// IK's tolerance, and the current choice stays reachable while its IK ends
// within `keep_tolerance` (a target at the edge of the workspace crosses the
// IK's tolerance back and forth with the sensor's noise) and its clearances
// (table, keeps, the person's hand and object) fall short of theirs by less
// than keep_tolerance.position. IK starts warm from each
// candidate's previous solution; a candidate without one (first update, or its
// warm solve failed) is solved from the current q and every fixed seed on the
// first update, keeping the best-scoring solution; later, such candidates get
// one seed each, round-robin, at most `cold_solves_per_update` solves per
// update, so candidates that stay out of reach cost little. A warm candidate
// is also solved from the current q (`branch_solves_per_update`, the better
// solution kept): a warm start keeps the IK branch a candidate was first found
// on, and the arm may have moved onto another. The chosen
// configuration is meant as the posture task's reference (redundancy
// resolution).
//
// Frames: object pose and outputs in the world; configurations in rad.
// Real-time safety: the constructor allocates; update() does not (all storage
// is sized by the constructor) and throws nothing. Its cost is bounded by the
// number of candidates x IK iterations: see docs/performance.md.
#pragma once

#include <vector>

#include "control/grasp/grasp_selection_config.hpp"

namespace handover::control::grasp {

/// What update() learned about one candidate.
struct CandidateEvaluation {
  bool evaluated = false;       ///< solved in the last update (false: skipped by the cold budget)
  bool feasible = false;        ///< grasp and pre-grasp IK both converged, the arm above the table
  Isometry grasp = Isometry::Identity();      ///< world
  Isometry pre_grasp = Isometry::Identity();  ///< world
  Vector7 q_grasp = Vector7::Zero();
  Vector7 q_pre_grasp = Vector7::Zero();
  ScoreTerms score;
  int iterations = 0;           ///< IK iterations spent on it in the last update
};

struct GraspChoice {
  bool valid = false;           ///< false: no candidate is reachable
  int index = -1;               ///< into GraspSelector::candidates()
  Isometry grasp = Isometry::Identity();      ///< world grasp frame to track
  Isometry pre_grasp = Isometry::Identity();  ///< world pre-grasp frame
  Isometry grasp_in_object = Isometry::Identity();  ///< the chosen candidate, fixed in the object frame
  Vector7 q_grasp = Vector7::Zero();          ///< rad, IK configuration at the grasp (posture reference)
  Vector7 q_pre_grasp = Vector7::Zero();      ///< rad, IK configuration at the pre-grasp
  ScoreTerms score;
  bool switched = false;        ///< the last update changed the index
};

class GraspSelector {
 public:
  /// Enumerates the candidates of `specs` and sizes every buffer. Throws
  /// std::invalid_argument when `specs` is empty, std::out_of_range when
  /// config.frame is not a frame of the model. `model` must outlive the selector.
  GraspSelector(const Model& model, const std::vector<GraspSpec>& specs, const GraspSelectionConfig& config);

  /// One selection for the object at X_obj (world), the arm at q_now (rad) and
  /// optional obstacle capsules (world). Real-time safe. A non-finite object
  /// pose or configuration (a sensor dropout gone wrong) changes nothing and
  /// returns the previous choice with `switched` false.
  const GraspChoice& update(const Isometry& X_obj, const Vector7& q_now, const ObstacleCapsule* obstacles = nullptr,
                            int num_obstacles = 0);

  /// The direction (world, unit; zero: none) a receiver will pull the object
  /// out of the open gripper: candidates whose fingers or palm would block it
  /// lose config.score.exit x exitBlock (grasp_score.hpp) x (free axis .
  /// approach axis)^2, the share of the turn about the free axis that turns
  /// the fingers about their approach axis (a wrist turn over a vertical
  /// approach) rather than swinging the approach around the object: a side
  /// presentation, upright or tilted, could free the pull only by swinging
  /// the gripper into the receiver's reach.
  /// Real-time safe.
  void setPullDirection(const Vector3& pull) { pull_ = pull; }

  /// Forgets warm starts and the current choice (a new object or a new approach).
  void reset();
  /// While on, the current choice is kept as long as it stays feasible, whatever
  /// the others score: once the arm has set off toward where the object will be,
  /// a switch costs a reorientation (up to a half turn of the wrist) that no score
  /// gain repays. Real-time safe.
  void holdChoice(bool on) { hold_ = on; }

  const GraspChoice& choice() const { return choice_; }
  const std::vector<GraspCandidate>& candidates() const { return candidates_; }
  const std::vector<CandidateEvaluation>& evaluations() const { return evaluations_; }
  const GraspSelectionConfig& config() const { return config_; }

 private:
  enum class Start { kWarm, kNextSeed, kAllSeeds };
  void evaluate(int k, const Isometry& X_obj, const Vector7& q_now, const ObstacleCapsule* obstacles,
                int num_obstacles, Start start);
  /// Candidate k (solved warm in this update) from q_now too; keeps the better solution.
  void tryCurrentBranch(int k, const Vector7& q_now, const ObstacleCapsule* obstacles, int num_obstacles);
  /// The candidate's own terms on a feasible solution: its spec's preference, the blocked pull.
  void addCandidateTerms(int k, ScoreTerms& score) const;
  /// keep: the candidate is the current choice (IK within config.keep_tolerance counts as reached).
  bool solvePair(const Isometry& grasp, const Isometry& pre_grasp, const Vector7& seed, const Vector7& q_now,
                 const ObstacleCapsule* obstacles, int num_obstacles, CandidateEvaluation& out, bool keep = false);

  const Model& model_;
  GraspSelectionConfig config_;
  int frame_ = 0;
  std::vector<GraspCandidate> candidates_;
  std::vector<CandidateEvaluation> evaluations_;
  std::vector<double> preference_;  ///< candidate k's spec's preference (score units)
  std::vector<Vector3> turn_axis_;  ///< candidate k's spec's free axis in its grasp frame (zero: none)
  std::vector<bool> warm_;      ///< candidate k has a converged solution to start from
  std::vector<bool> solved_warm_;  ///< candidate k was solved from its warm start in this update
  std::vector<int> next_seed_;  ///< candidate k's next cold seed (index into seeds_)
  std::vector<Vector7> seeds_;  ///< [q_now, fixed seeds...], slot 0 rewritten each update
  int cold_cursor_ = 0;         ///< round-robin start of the cold budget
  int branch_cursor_ = 0;       ///< round-robin start of the branch budget
  bool hold_ = false;
  Vector3 pull_ = Vector3::Zero();
  GraspChoice choice_;
};

}  // namespace handover::control::grasp
