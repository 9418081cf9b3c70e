// Grasp selection and IK allocate nothing after construction: every call to
// the C allocator (which operator new and Eigen both end in) is counted
// while 300 selector updates, IK solves and an upright search run.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>

#include "control/grasp/grasp_selector.hpp"
#include "control/grasp/upright_placement.hpp"
#include "tests/control/grasp/panda_fixture.hpp"

namespace {
std::atomic<bool> g_count{false};
std::atomic<long> g_mallocs{0};
}  // namespace

// glibc's own entry points, so that this binary's malloc can count and forward
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t n) {
  if (g_count.load(std::memory_order_relaxed)) ++g_mallocs;
  return __libc_malloc(n);
}
void* calloc(std::size_t k, std::size_t n) {
  if (g_count.load(std::memory_order_relaxed)) ++g_mallocs;
  return __libc_calloc(k, n);
}
void* realloc(void* p, std::size_t n) {
  if (g_count.load(std::memory_order_relaxed)) ++g_mallocs;
  return __libc_realloc(p, n);
}
}

namespace handover::control::grasp {
namespace {

// counts the allocations made while `f` runs
template <typename F>
long allocationsDuring(F&& f) {
  g_mallocs = 0;
  g_count = true;
  f();
  g_count = false;
  return g_mallocs.load();
}

TEST(GraspAllocation, TheCounterSeesAllocations) {
  std::vector<double>* v = nullptr;
  EXPECT_GE(allocationsDuring([&] { v = new std::vector<double>(100); }), 1);
  delete v;
}

TEST(GraspAllocation, UpdatesSolvesAndUprightSearchAllocateNothing) {
  const Model& model = testing::panda();
  GraspSpec side;
  side.placement.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  side.has_free_axis = true;
  GraspSelector selector(model, {side}, testing::shippedConfig());
  const ObstacleCapsule forearm{Vector3(0.8, 0.2, 0.3), Vector3(0.6, 0.1, 0.3), 0.04};
  const int tcp = model.frameId("tcp");
  HeldObject held;
  held.object_in_tcp.linear() = Eigen::AngleAxisd(-M_PI / 2, Vector3::UnitY()).toRotationMatrix();
  long feasible = 0;
  const long allocations = allocationsDuring([&] {
    for (int k = 0; k < 300; ++k) {
      // the object sweeps through and out of reach and back: warm, cold and failing paths
      Isometry X = Isometry::Identity();
      X.translation() = Vector3(0.55 + 0.6 * std::max(0.0, std::sin(0.05 * k)), 0.2 * std::sin(0.03 * k), 0.3);
      const GraspChoice& c = selector.update(X, testing::readyConfiguration(), &forearm, 1);
      feasible += c.valid;
      if (k % 50 == 0) selector.reset();
      const IkResult r = solveIk(model, tcp, X, testing::readyConfiguration(), testing::shippedConfig().ik);
      feasible += r.converged;
    }
    feasible += findUprightPlacement(model, held, Vector3(0.35, 0.0, 0.4), testing::readyConfiguration(),
                                     testing::shippedConfig()).found;
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(feasible, 100);  // the loop did real work
}

}  // namespace
}  // namespace handover::control::grasp
