// Parking benchmarks: simulation steps per second (empty lot and parked-car lot) and expert planning time.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "engine/core/rng.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking/parking_sim.hpp"

namespace {

void run_sim_steps(benchmark::State& state, sc::LotVariant variant) {
  sc::ParkingScenario scenario;
  scenario.heading0 = 0.3;
  scenario.goal_spot = 4;
  scenario.variant = variant;
  scenario.obstacle_seed = 9;
  sc::ParkingSim sim(scenario);
  int t = 0;
  for (auto _ : state) {
    if (sim.done()) sim.reset();
    // A gentle slalom in the aisle: stays clear of obstacles so every step does the full collision test.
    const sc::ParkingStepResult r = sim.step({t % 20 < 10 ? 0.3 : -0.3, std::sin(0.3 * t)});
    benchmark::DoNotOptimize(r);
    ++t;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_ParkingSimStepClassic(benchmark::State& state) { run_sim_steps(state, sc::LotVariant::Classic); }
void BM_ParkingSimStepParked(benchmark::State& state) { run_sim_steps(state, sc::LotVariant::Parked); }

void run_expert(benchmark::State& state, sc::LotVariant variant) {
  sc::Rng rng(11);
  std::vector<sc::ParkingScenario> scenarios;
  for (int i = 0; i < 32; ++i) scenarios.push_back(sc::sample_parking_scenario(rng, variant));
  const sc::ParkingExpert expert;
  std::size_t i = 0;
  for (auto _ : state) {
    const sc::ParkingPlan plan = expert.plan(scenarios[i++ % scenarios.size()]);
    benchmark::DoNotOptimize(plan.actions.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ParkingExpertPlanClassic(benchmark::State& state) { run_expert(state, sc::LotVariant::Classic); }
void BM_ParkingExpertPlanParked(benchmark::State& state) { run_expert(state, sc::LotVariant::Parked); }

}  // namespace

BENCHMARK(BM_ParkingSimStepClassic);
BENCHMARK(BM_ParkingSimStepParked);
BENCHMARK(BM_ParkingExpertPlanClassic)->Unit(benchmark::kMillisecond)->Iterations(64);
BENCHMARK(BM_ParkingExpertPlanParked)->Unit(benchmark::kMillisecond)->Iterations(64);
