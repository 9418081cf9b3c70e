#include "fsm/handover/withdrawal_watch.hpp"

#include "fsm/handover/perception_checks.hpp"

namespace handover::fsm {

bool WithdrawalWatch::withdrawn(const HandoverContext& ctx, bool hand) {
  if (const std::optional<bool> at_once = withdrawnAtOnce(ctx, hand)) return *at_once;
  const HandoverParams& p = *ctx.params;
  const SensedBody& body = hand ? ctx.in.hand : ctx.in.object;
  // a reach still under way that ends far out goes away from the workspace centre too: until the
  // body has come to rest once, only a way back home is leaving (offered while it still moved, a
  // reach toward the arm's far edge was taken for a withdrawal, three times until the take
  // aborted: g643_00164)
  if (body.velocity.head<3>().norm() <= p.arrive_speed) arrived_ = true;
  // taken back to where it was before the reach, however slowly: a person who brought the object
  // 8 cm out and carried it home at 0.1 m/s held it there while the arm came and took it (g727_00042)
  const Vector3* home = homeOf(ctx, hand);
  if (p.withdraw_home_radius > 0.0 && home != nullptr) {
    const double from_home = (body.pose.translation() - *home).norm();
    if (from_home > 2.0 * p.withdraw_home_radius) left_home_ = true;
    else if (left_home_ && from_home < p.withdraw_home_radius) return true;
  }
  const bool home_bound = headingHome(ctx, hand);
  if (!home_bound && !(arrived_ && movingAway(ctx, hand))) {
    leaving_ = false;
    return false;
  }
  const Vector3 at = body.pose.translation();
  if (!leaving_) {
    leaving_ = true;
    from_ = at;
  }
  // carried away far enough, or heading home (so it is known) and nearly there (a reach taken back early is short)
  return (at - from_).norm() >= p.withdraw_distance || (home_bound && (at - *home).norm() <= p.withdraw_distance);
}

}  // namespace handover::fsm
