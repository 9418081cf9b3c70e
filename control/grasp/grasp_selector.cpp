#include "control/grasp/grasp_selector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace handover::control::grasp {

GraspSelector::GraspSelector(const Model& model, const std::vector<GraspSpec>& specs,
                             const GraspSelectionConfig& config)
    : model_(model), config_(config), frame_(model.frameId(config.frame)) {
  if (specs.empty()) throw std::invalid_argument("GraspSelector: the object declares no grasp");
  candidates_ = enumerateGraspCandidates(specs, config.candidates);
  evaluations_.resize(candidates_.size());
  for (const GraspCandidate& c : candidates_) {
    const GraspSpec& spec = specs[static_cast<std::size_t>(c.spec)];
    preference_.push_back(spec.preference);
    // the free axis in the candidate's own grasp frame (zero without one)
    turn_axis_.push_back(spec.has_free_axis ? Vector3(c.in_object.linear().transpose() * spec.free_axis.normalized())
                                            : Vector3::Zero());
  }
  warm_.assign(candidates_.size(), false);
  solved_warm_.assign(candidates_.size(), false);
  next_seed_.assign(candidates_.size(), 0);
  seeds_.reserve(config.seeds.size() + 1);
  seeds_.push_back(Vector7::Zero());
  seeds_.insert(seeds_.end(), config.seeds.begin(), config.seeds.end());
}

void GraspSelector::reset() {
  std::fill(warm_.begin(), warm_.end(), false);
  std::fill(next_seed_.begin(), next_seed_.end(), 0);
  for (CandidateEvaluation& e : evaluations_) e = CandidateEvaluation();
  choice_ = GraspChoice();
  cold_cursor_ = 0;
  branch_cursor_ = 0;
}

bool GraspSelector::solvePair(const Isometry& grasp, const Isometry& pre_grasp, const Vector7& seed,
                              const Vector7& q_now, const ObstacleCapsule* obstacles, int num_obstacles,
                              CandidateEvaluation& out, bool keep) {
  const auto reached = [&](const IkResult& r) {
    return r.converged || (keep && r.position_error < config_.keep_tolerance.position &&
                           r.orientation_error < config_.keep_tolerance.orientation);
  };
  const IkResult g = solveIk(model_, frame_, grasp, seed, config_.ik);
  out.iterations += g.iterations;
  if (!reached(g)) return false;
  // no standoff (a give's presentation): the pre-grasp is the grasp, solved and scored once
  const bool has_pre = pre_grasp.matrix() != grasp.matrix();
  // the pre-grasp lies a few cm back: its solution is next to the grasp's
  const IkResult p = has_pre ? solveIk(model_, frame_, pre_grasp, g.q, config_.ik) : g;
  if (has_pre) out.iterations += p.iterations;
  if (!reached(p)) return false;

  ChainPoses poses;
  // the current choice passes every clearance test within keep_tolerance.position, as it passes the
  // IK's within keep_tolerance: a grasp at the edge of a keep crossed it back and forth with the
  // sensor's noise (1-2 mm), was dropped and taken again every 0.1-0.3 s, and the target jumped
  // between two grasps 10 cm apart for 10 s (g1101_00584)
  const double band = keep ? config_.keep_tolerance.position : 0.0;
  const double floor = config_.table_height + config_.table_clearance - band;
  ScoreTerms pre;
  if (has_pre) {
    chainPoses(model_, p.q, poses);
    if (lowestArmPoint(model_, poses) < floor) return false;
    // the arm passes the pre-grasp on its way in: inside the keeps there, it stopped at the person's
    // chest short of it until they let the ball fall (g727_00117)
    if (config_.reject_inside_keeps && personBodyClearance(model_, poses, obstacles, num_obstacles) < -band) return false;
    // where the arm lines up, the fingers are still in front of the object, not in it
    if (heldObjectClearance(model_, poses, obstacles, num_obstacles) < -band) return false;
    pre = scoreConfiguration(model_, frame_, poses, p.q, q_now, obstacles, num_obstacles, config_.score);
  }
  chainPoses(model_, g.q, poses);
  if (lowestArmPoint(model_, poses) < floor) return false;
  // only the fingers go around the object in the person's hand: a grasp that puts the palm
  // (or the arm) in that hand is no grasp (a ball on the palm taken from the side: the palm
  // struck the hand under it)
  if (workZoneClearance(model_, poses, obstacles, num_obstacles) < -band) return false;
  // nor one that brings any of it, the fingers too, nearer the person's arm or trunk than the collision
  // constraints let it go: the arm stopped short of it until the person gave up (g1_00184, a
  // ball on a palm taken at 45 degrees over the wrist). There the fingers share the object with the
  // person's hand (a take's grasp: the constraints keep the gripper only sDist from the arm that
  // holds it); the pre-grasp, on the way in, keeps what the approach keeps
  if (config_.reject_inside_keeps && personBodyClearance(model_, poses, obstacles, num_obstacles, has_pre) < -band)
    return false;
  ScoreTerms t = scoreConfiguration(model_, frame_, poses, g.q, q_now, obstacles, num_obstacles, config_.score);
  if (has_pre) {
    // the arm must pass the pre-grasp too: the worse margin and clearance count
    t.joint_margin = std::min(t.joint_margin, pre.joint_margin);
    t.clearance = std::max(t.clearance, pre.clearance);
    t.total = totalScore(t, config_.score);
  }
  out.q_grasp = g.q;
  out.q_pre_grasp = p.q;
  out.score = t;
  return true;
}

void GraspSelector::evaluate(int k, const Isometry& X_obj, const Vector7& q_now, const ObstacleCapsule* obstacles,
                             int num_obstacles, Start start) {
  CandidateEvaluation& e = evaluations_[k];
  e.evaluated = true;
  e.iterations = 0;
  e.grasp = graspInWorld(X_obj, candidates_[k]);
  e.pre_grasp = preGraspOf(e.grasp, config_.candidates.pre_grasp_standoff);

  if (start == Start::kWarm || start == Start::kNextSeed) {
    int& next = next_seed_[k];
    const Vector7 seed = start == Start::kWarm ? e.q_grasp : seeds_[next];
    if (start == Start::kNextSeed) next = (next + 1) % static_cast<int>(seeds_.size());
    const bool keep = choice_.valid && choice_.index == k;
    e.feasible = solvePair(e.grasp, e.pre_grasp, seed, q_now, obstacles, num_obstacles, e, keep);
    warm_[k] = e.feasible;
    if (e.feasible) addCandidateTerms(k, e.score);
    return;
  }
  // every seed, keep the best-scoring solution
  CandidateEvaluation trial;
  e.feasible = false;
  for (const Vector7& seed : seeds_) {
    trial.iterations = 0;
    const bool ok = solvePair(e.grasp, e.pre_grasp, seed, q_now, obstacles, num_obstacles, trial);
    e.iterations += trial.iterations;
    if (ok && (!e.feasible || trial.score.total > e.score.total)) {
      e.feasible = true;
      e.q_grasp = trial.q_grasp;
      e.q_pre_grasp = trial.q_pre_grasp;
      e.score = trial.score;
    }
  }
  warm_[k] = e.feasible;
  if (e.feasible) addCandidateTerms(k, e.score);
}

void GraspSelector::tryCurrentBranch(int k, const Vector7& q_now, const ObstacleCapsule* obstacles,
                                     int num_obstacles) {
  CandidateEvaluation& e = evaluations_[k];
  CandidateEvaluation trial;
  const bool ok = solvePair(e.grasp, e.pre_grasp, q_now, q_now, obstacles, num_obstacles, trial);
  e.iterations += trial.iterations;
  if (!ok) return;
  addCandidateTerms(k, trial.score);
  if (trial.score.total <= e.score.total) return;  // e is feasible: solved warm in this update
  e.q_grasp = trial.q_grasp;
  e.q_pre_grasp = trial.q_pre_grasp;
  e.score = trial.score;
}

void GraspSelector::addCandidateTerms(int k, ScoreTerms& score) const {
  const std::size_t i = static_cast<std::size_t>(k);
  score.preference = preference_[i];
  // counted by the share of the turn about the free axis that turns the
  // fingers about their own approach axis (the wrist, cos^2), not the
  // approach around the object (sin^2)
  const double wrist = turn_axis_[i].z() * turn_axis_[i].z();
  score.exit = exitBlock(evaluations_[i].grasp, pull_) * wrist;
  score.total += score.preference - config_.score.exit * score.exit;
}

const GraspChoice& GraspSelector::update(const Isometry& X_obj, const Vector7& q_now, const ObstacleCapsule* obstacles,
                                         int num_obstacles) {
  if (!X_obj.matrix().allFinite() || !q_now.allFinite()) {
    choice_.switched = false;
    return choice_;
  }
  seeds_[0] = q_now;
  const int n = static_cast<int>(candidates_.size());
  // Warm candidates every time. The others (unreachable so far, or lost):
  // from every seed while nothing is reachable yet (a new object) or when the
  // budget is 0; else one seed each, round-robin over candidates and seeds,
  // at most `cold_solves_per_update` of them.
  const bool any_warm = std::find(warm_.begin(), warm_.end(), true) != warm_.end();
  const bool all_seeds = !any_warm || config_.cold_solves_per_update == 0;
  const int branch_budget = config_.branch_solves_per_update > 0 ? config_.branch_solves_per_update : n;
  int cold_done = 0, last_cold = -1, branch_done = 0, last_branch = -1;
  for (int i = 0; i < n; ++i) {
    const int k = (cold_cursor_ + i) % n;
    solved_warm_[k] = false;
    if (warm_[k]) {
      evaluate(k, X_obj, q_now, obstacles, num_obstacles, Start::kWarm);
      solved_warm_[k] = warm_[k];
      if (warm_[k]) continue;  // a failed warm solve falls through to a cold one
    }
    if (all_seeds) {
      evaluate(k, X_obj, q_now, obstacles, num_obstacles, Start::kAllSeeds);
    } else if (cold_done < config_.cold_solves_per_update) {
      evaluate(k, X_obj, q_now, obstacles, num_obstacles, Start::kNextSeed);
      ++cold_done;
      last_cold = k;
    } else {
      evaluations_[k].evaluated = false;
      evaluations_[k].feasible = false;
      evaluations_[k].iterations = 0;
    }
  }
  // the next update's cold solves start after the last one of this update
  if (last_cold >= 0) cold_cursor_ = (last_cold + 1) % n;
  // the branch the arm is on now, for candidates solved warm on another one
  for (int i = 0; i < n && branch_done < branch_budget; ++i) {
    const int k = (branch_cursor_ + i) % n;
    if (!solved_warm_[k]) continue;
    tryCurrentBranch(k, q_now, obstacles, num_obstacles);
    ++branch_done;
    last_branch = k;
  }
  if (last_branch >= 0) branch_cursor_ = (last_branch + 1) % n;

  // best feasible candidate; the current one keeps its place unless beaten by the margin
  int best = -1;
  for (int k = 0; k < n; ++k) {
    if (evaluations_[k].feasible && (best < 0 || evaluations_[k].score.total > evaluations_[best].score.total)) best = k;
  }
  const int current = choice_.valid ? choice_.index : -1;
  int pick = best;
  if (current >= 0 && evaluations_[current].feasible &&
      (hold_ || evaluations_[best].score.total <= evaluations_[current].score.total + config_.hysteresis)) {
    pick = current;
  }
  choice_.switched = pick != current;
  choice_.valid = pick >= 0;
  choice_.index = pick;
  if (pick >= 0) {
    const CandidateEvaluation& e = evaluations_[pick];
    choice_.grasp = e.grasp;
    choice_.grasp_in_object = candidates_[pick].in_object;
    choice_.pre_grasp = e.pre_grasp;
    choice_.q_grasp = e.q_grasp;
    choice_.q_pre_grasp = e.q_pre_grasp;
    choice_.score = e.score;
  }
  return choice_;
}

}  // namespace handover::control::grasp
