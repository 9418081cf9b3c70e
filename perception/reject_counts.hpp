// Why pose samples were refused, and how many of each. The estimator's
// plausibility gates (perception/plausibility_gate.hpp) and the sources'
// decoders (malformed datagrams) fill it; the run reports it (summary.json
// `tracker.rejected`, the screen summary, log.csv `rejected_*`).
// Plain data, real-time safe.
#pragma once

#include <array>

namespace handover::perception {

enum class RejectReason : int {
  kMalformed = 0,  ///< the source could not decode it (a UDP datagram with a wrong field, ...)
  kInvalid,        ///< a non-finite number or a quaternion that is not of unit norm
  kTime,           ///< stamped before the latest accepted sample, or later than its arrival (a clock fault)
  kWorkspace,      ///< a body outside the workspace box (no person can be there)
  kJump,           ///< a body moved farther than max_jump since the last accepted sample
  kSpeed,          ///< ... faster than max_speed (beyond the noise tolerance)
  kAcceleration,   ///< ... away from the constant-velocity prediction by more than max_acceleration allows
  kCount
};
constexpr int kRejectReasons = static_cast<int>(RejectReason::kCount);

/// Lower-case name as written in summary.json and log.csv ("workspace", ...).
inline const char* toString(RejectReason r) {
  switch (r) {
    case RejectReason::kMalformed: return "malformed";
    case RejectReason::kInvalid: return "invalid";
    case RejectReason::kTime: return "time";
    case RejectReason::kWorkspace: return "workspace";
    case RejectReason::kJump: return "jump";
    case RejectReason::kSpeed: return "speed";
    case RejectReason::kAcceleration: return "acceleration";
    case RejectReason::kCount: break;
  }
  return "?";
}

struct RejectCounts {
  std::array<long, kRejectReasons> count{};  ///< per RejectReason, in enum order

  void add(RejectReason r, long n = 1) { count[static_cast<std::size_t>(r)] += n; }
  long operator[](RejectReason r) const { return count[static_cast<std::size_t>(r)]; }
  long total() const {
    long n = 0;
    for (long c : count) n += c;
    return n;
  }
  RejectCounts& operator+=(const RejectCounts& o) {
    for (std::size_t i = 0; i < count.size(); ++i) count[i] += o.count[i];
    return *this;
  }
};

}  // namespace handover::perception
