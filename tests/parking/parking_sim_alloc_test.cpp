// ParkingSim::step must not allocate: a replaced global operator new counts allocations in this binary.
#include <atomic>
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "engine/parking/parking_sim.hpp"

namespace {
std::atomic<long> g_allocations{0};  // test-only instrumentation of the replaced operator new
}

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
// GCC 12 (at -O1 and above) warns that free() gets a pointer "from operator new": a false positive here,
// since this very operator new took it from malloc. Silenced for these two definitions only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace sc {
namespace {

long steps_allocations(LotVariant variant) {
  ParkingScenario s;
  s.heading0 = 0.4;
  s.goal_spot = 12;
  s.variant = variant;
  s.obstacle_seed = 11;
  ParkingSim sim(s);  // construction may allocate (the layout)
  const long before = g_allocations.load();
  int steps = 0;
  for (int episode = 0; episode < 3; ++episode) {
    sim.reset();
    for (int t = 0; t < 100 && !sim.done(); ++t, ++steps) sim.step({0.3 * (t % 5) - 0.5, 0.9 - 0.04 * t});
  }
  EXPECT_GT(steps, 20);
  return g_allocations.load() - before;
}

TEST(ParkingSimAllocations, CountingWorks) {
  const long before = g_allocations.load();
  // A direct call (a new-expression could legally be optimised away).
  void* p = ::operator new(16);
  ::operator delete(p);
  EXPECT_EQ(g_allocations.load() - before, 1);
}

TEST(ParkingSimAllocations, StepIsAllocationFreeInBothVariants) {
  EXPECT_EQ(steps_allocations(LotVariant::Classic), 0);
  EXPECT_EQ(steps_allocations(LotVariant::Parked), 0);
}

}  // namespace
}  // namespace sc
