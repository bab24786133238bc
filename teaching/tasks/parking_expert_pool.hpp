#pragma once
// The parking expert pool: ParkingExpert plans for random classic scenarios, deterministic in the seed.
// Planning costs ~20-50 ms per scenario, so the pool ships as a JSON file (assets/experts/parking_pool.json,
// written by `skillcoach expert-pool`) and is loaded at start; a missing or unusable file is regenerated.
//
// Two pools ship: the whole lot (what free practice and later sessions use) and the study corner (the
// paper's user study drew goals from the bottom-right spots only, because the whole lot needs many more
// skills; a learner's first parking session uses it).
//
// File format: {"format":"skillcoach-parking-expert-pool","version":1,"seed":S,"count":N,
//               "region":"whole-lot"|"study-corner" (missing: whole-lot),
//               "trials":[<parking trial document, source "expert">, ...]}
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/parking/parking_trial.hpp"

namespace sc {

struct ParkingPoolOptions {
  int count = 100;         // the reference's CompILE data set had 100 rollouts
  std::uint64_t seed = 0;  // scenario i is parking_pool_scenario(seed, i, region)
  GoalRegion region = GoalRegion::WholeLot;
};

// Scenario i of a pool: sample_parking_scenario(Rng(seed).fork(i), Classic, 0, region). Also used to draw
// fresh scenarios with another seed.
ParkingScenario parking_pool_scenario(std::uint64_t seed, int index, GoalRegion region = GoalRegion::WholeLot);

// Plans every scenario (cost: count x ~20-50 ms). Deterministic.
std::vector<ParkingTrial> generate_parking_pool(const ParkingPoolOptions& options);

Json parking_pool_json(const ParkingPoolOptions& options, const std::vector<ParkingTrial>& trials);
// Throws InputError naming the file and JSON path for a malformed document, or when its seed/count differ
// or region differ from `expected` (the file belongs to another configuration).
std::vector<ParkingTrial> parse_parking_pool(const Json& doc, const std::string& source,
                                             const ParkingPoolOptions& expected);

struct LoadedParkingPool {
  std::vector<ParkingTrial> trials;
  // Empty when the file was read; otherwise why the pool was regenerated (and whether it was saved).
  std::string notice;
};

// Reads `file`; when it is missing or unusable, generates the pool and tries to write it back (a
// read-only install keeps the pool in memory and says so in the notice).
LoadedParkingPool load_or_generate_parking_pool(const std::filesystem::path& file, const ParkingPoolOptions& options);

}  // namespace sc
