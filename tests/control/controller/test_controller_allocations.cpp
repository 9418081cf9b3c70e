// The control step must not allocate: count every global operator new over
// 1000 controller steps after construction (with tracking, observation,
// posture, limits, moving targets and a grasp offset with a free axis).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "control/controller.hpp"
#include "control/so3.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& t) noexcept { return operator new(size, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace handover::control;

TEST(ControllerAllocations, NoHeapAllocationInTheControlStep) {
  const Model model = loadModel(std::string(HANDOVER_SOURCE_DIR) + "/scenes/panda.urdf");
  Controller ctl(model, loadControllerConfig(defaultControllerConfigPath()));
  ControlInputs in;
  in.q = ctl.config().posture.target;
  ctl.reset(in);
  GraspOffset offset;
  offset.placement.translation() = Vector3(0, 0, 0.02);
  offset.has_free_axis = true;
  Isometry target = ctl.tcpPose();
  // the wrist load estimator the cycle runs before each step (runtime/handover_cycle.cpp, stage 6b)
  ContactWrenchSettings cws;
  cws.feed_forward = ContactWrenchSettings::FeedForward::kAlways;
  ContactWrenchEstimator load(model, cws, ctl.config().period);
  Payload object;
  object.mass = 1.0;
  load.start(object, false);
  ContactWrenchInput cw;

  // sanity: the counter works
  g_counting = true;
  {
    void* p = ::operator new(16);  // a call, not a new-expression: cannot be elided
    ::operator delete(p);
  }
  g_counting = false;
  ASSERT_EQ(g_allocations.load(), 1);
  g_allocations = 0;

  Vector7 q = in.q, v = Vector7::Zero();
  const double dt = ctl.config().period;
  g_counting = true;
  for (int k = 0; k < 1000; ++k) {
    // the state machine's per-cycle calls
    target.translation() += Vector3(1e-4, 0.0, -5e-5);
    ctl.setObservationTarget(target, k % 17 != 0);
    if (k == 100) ctl.setGraspOffset(offset);
    if (k == 200) ctl.setTaskEnabled("posture", false);
    if (k == 300) ctl.setTaskEnabled("posture", true);
    if (k == 400) ctl.setSpeedScale(0.5);
    if (k == 500) ctl.setTaskEnabled("pose", true);
    cw.sensor_rotation = framePlacement(ctl.model(), ctl.data(), ctl.model().frameId("ft_sensor")).linear();
    // the hand's weight, and from k = 500 a 1 kg object's (world -z), in sensor axes
    cw.reading.head<3>() = cw.sensor_rotation.transpose() * Vector3(0.3, -0.2, -7.5 - (k > 500 ? 9.81 : 0.0));
    cw.reading.tail<3>() = Vector3(0.01, 0.02, 0.0);
    cw.sensor_acceleration = ctl.sensorAcceleration();
    cw.at_rest = k < 300;
    cw.gripper_closed = k > 400;
    load.update(cw);
    ctl.setPayload(load.payload());
    ctl.setExternalWrench(load.feedForward());
    in.time = k * dt;
    in.q = q;
    in.qd = v;
    ctl.step(in);
    (void)ctl.graspFrame();
    (void)ctl.tcpVelocity();
    v += ctl.lastQdd() * dt;
    q += v * dt;
  }
  // and the fallback path
  in.q[0] = std::nan("");
  ctl.step(in);
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_EQ(ctl.fallbackCount(), 1);  // only the NaN step fell back
  EXPECT_GT(load.loadShare(), 0.5);   // the estimator really ran: it saw the added weight
}
