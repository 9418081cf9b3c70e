// How much of a run the controller may spend in its QP fallback (the damped
// stop) before the run is stopped: when the QP failed in more than
// `max_share` of the control steps of the last `window` seconds, the
// controller cannot keep its constraints (absurd settings or inputs), the arm
// is held by the damped stop and the limit guard, and nothing useful can
// follow. The run then ends there (still `unsafe`: the QP failed), with a
// message that says why, instead of alternating between failed and relaxed
// solves for the rest of its duration (config/controller.yaml
// fallback.max_share, fallback.window; docs/safety.md).
//
// A ring of the last `window` steps: observe() is O(1) and allocates nothing
// (the ring is sized at construction). Header-only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace handover::app {

class FallbackBudget {
 public:
  /// `window` s of `dt` s steps; `max_share` in (0, 1]; max_share >= 1 never stops.
  FallbackBudget(double window, double dt, double max_share)
      : ring_(static_cast<std::size_t>(std::max(1.0, std::round(window / dt))), 0), max_share_(max_share) {}

  /// One control step; returns true once the budget is exhausted.
  bool observe(bool fell_back) {
    count_ += (fell_back ? 1 : 0) - ring_[next_];
    ring_[next_] = fell_back ? 1 : 0;
    next_ = (next_ + 1) % ring_.size();
    return max_share_ < 1.0 && static_cast<double>(count_) > max_share_ * static_cast<double>(ring_.size());
  }
  /// Failed steps in the window.
  int count() const { return count_; }
  std::size_t windowSteps() const { return ring_.size(); }

 private:
  std::vector<unsigned char> ring_;
  std::size_t next_ = 0;
  int count_ = 0;
  double max_share_;
};

}  // namespace handover::app
