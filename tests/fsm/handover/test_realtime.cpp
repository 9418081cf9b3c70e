// step() allocates nothing once loaded: a whole take and a whole give, with
// every transition, the safety overlay and a preemption, run under a global
// allocation counter. (Speed is measured by the benchmark, not here.)
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "tests/fsm/handover/fake_world.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace handover::fsm::test {
namespace {

TEST(HandoverRealtime, CounterSeesAllocations) {
  const long before = g_allocations.load();
  // kept in a volatile pointer: a new/delete pair the optimiser can see through may be elided
  static std::vector<double>* volatile kept;
  kept = new std::vector<double>(100);
  delete kept;
  EXPECT_GE(g_allocations.load() - before, 2);
}

TEST(HandoverRealtime, TakeWithSafetyEventsDoesNotAllocate) {
  Rig rig;
  rig.ctl.record = false;
  rig.world.moveHand(Vector3(0.55, 0.0, 0.30), 0.5);
  auto gripped_since = std::make_shared<double>(-1.0);
  rig.person = [gripped_since](World& w) {
    if (w.time > 0.1 && w.time < 0.15) w.arm_distance = 0.15;      // slow down
    else if (w.time > 0.2 && w.time < 0.3) w.arm_distance = 0.02;  // stop
    else w.arm_distance = 1.0;
    if (!w.robot_grip) return;
    if (*gripped_since < 0) *gripped_since = w.time;
    if (w.time - *gripped_since >= 0.1 && w.person_holds) {
      w.person_holds = false;
      w.moveHand(Vector3(1.0, -0.3, 0.2), 0.5);  // lets go and withdraws
    }
  };
  const long before = g_allocations.load();
  const bool done = rig.runUntil([&] { return rig.fsm->done(); }, 20.0);
  const long during = g_allocations.load() - before;
  ASSERT_TRUE(done) << rig.fsm->activePath();
  EXPECT_STREQ(rig.fsm->stats().outcome, "success");
  EXPECT_EQ(rig.fsm->stats().safety_stops, 1);
  EXPECT_EQ(during, 0);
}

TEST(HandoverRealtime, GiveDoesNotAllocate) {
  Rig rig(true);
  rig.ctl.record = false;
  rig.person = [](World& w) {
    if (w.time > 1.0 && !w.person_holds) w.moveHand(Vector3(0.60, 0.0, 0.35), 0.5);
    const bool in_hand = (w.object - (w.hand + w.object_in_hand)).norm() < 0.01 && w.tcp_vel.norm() < 0.01;
    if (in_hand && w.time > 4.0) w.person_holds = true;
    w.pull = w.person_holds ? Vector3(5.0, 0.0, 0.0) : Vector3::Zero();
  };
  const long before = g_allocations.load();
  const bool done = rig.runUntil([&] { return rig.fsm->done(); }, 20.0);
  const long during = g_allocations.load() - before;
  ASSERT_TRUE(done) << rig.fsm->activePath();
  EXPECT_STREQ(rig.fsm->stats().outcome, "success");
  EXPECT_EQ(during, 0);
}

}  // namespace
}  // namespace handover::fsm::test
