#pragma once
// TaskKit for car parking: the expert pool (ParkingExpert plans of random classic scenarios, cached in
// assets/experts/parking_pool.json), drills re-simulated from their first segment's car state, rewards
// as the reference's episode score (the last step's reward, <= 0).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "teaching/sessions/task_kit.hpp"
#include "teaching/tasks/parking_drill_projector.hpp"
#include "teaching/tasks/parking_drive_reading.hpp"
#include "teaching/tasks/parking_expert_pool.hpp"
#include "teaching/tasks/parking_skill_motion.hpp"

namespace sc {

inline constexpr int kParkingTimeSlices = 3;  // the paper's study: K = 3 for parking

struct ParkingKitOptions {
  // The cached pool; empty = generate in memory only. See default_parking_pool_file().
  std::filesystem::path pool_file;
  ParkingPoolOptions pool;
  // Quality-aware expertise's noise floor (execution_expertise.hpp). None by default: with one the
  // never-reversing and weak-steering learners' deficits were hidden, since a deficit's segments mostly score
  // within what noise does (docs/skills.md, "Quality-aware expertise"); `evaluate-diagnosis
  // --apply-noise-floor` measures it.
  std::optional<NoiseFloor> execution_noise_floor;
  // Research: read drives as before 2026-12-05 or 2026-12-06 (parking_drive_reading.hpp says how the kit reads
  // them, and why); `--read-whole-drives` and `--read-in-one-piece` of the evaluate commands.
  ParkingDriveReading reading = {};
};

// asset_dir()/experts/parking_pool.json, or parking_pool_study_corner.json for the study corner.
std::filesystem::path default_parking_pool_file(GoalRegion region = GoalRegion::WholeLot);
// longest_moving_drive of the shipped pool (generated when its file is missing, as the kit does): the piece length
// the kit reads drives with, for tools that read drives without a kit (`segment`, `evaluate-skills`).
int shipped_pool_piece_length();

class ParkingKit final : public TaskKit {
 public:
  // Loads (or generates, see load_or_generate_parking_pool) the pool and segments it with `extractor`
  // (any SkillExtractor: CompILE, or the time heuristic as a fallback), which extractor() wraps so that every
  // drive is read as parking_drive_reading.hpp says (options.reading), pieces as long as the pool's longest drive.
  // `extractor_notice` is passed through to extractor_notice().
  ParkingKit(std::shared_ptr<const SkillExtractor> extractor, std::string extractor_notice,
             const ParkingKitOptions& options);
  // With a ready pool (tests, tools): every trial needs control-rate actions and T+1 states; `region` says
  // where its goals lie (fresh scenarios are drawn there too).
  ParkingKit(std::shared_ptr<const SkillExtractor> extractor, std::string extractor_notice,
             std::vector<ParkingTrial> pool, GoalRegion region = GoalRegion::WholeLot);

  std::string task() const override { return "parking"; }
  const SkillExtractor& extractor() const override { return *extractor_; }
  std::string extractor_notice() const override { return extractor_notice_; }
  const std::vector<ExpertDemo>& expert_pool() const override { return demos_; }
  const DrillProjector& projector() const override { return *projector_; }
  // CurriculumConfig::parking() with min_skill_steps = 5: one second of driving (5 Hz control).
  CurriculumConfig curriculum_config() const override;

  StepSequence steps_of(const Json& trial) const override;
  // The trial's last recorded reward; trials without rewards are re-simulated from their actions.
  double reward_of(const Json& trial) const override;
  // The pool's expert trial when the scenario is in the pool, else a fresh ParkingExpert plan.
  Json expert_trial(const Json& scenario) const override;
  // Classic scenarios drawn like the pool's (parking_pool_scenario(seed, i, region), i = 0, 1, ...), skipping
  // any equal to one in `exclude` and duplicates. InputError for a malformed exclude entry.
  std::vector<Json> fresh_scenarios(int count, std::uint64_t seed, const std::vector<Json>& exclude) const override;
  std::string describe_skill(int skill) const override;
  // Rule: twice the expert's driving time (0.2 s per control step) plus 5 s to read the scene, capped at
  // the episode's 20 s horizon (ParkingSim ends the episode there anyway).
  double time_limit_seconds(int expert_steps) const override;
  Json drill_trial(const PlayableDrill& drill) const override;
  // reward_of(attempt); InputError when the attempt was played in another scenario than the drill's.
  double drill_attempt_reward(const PlayableDrill& drill, const Json& attempt) const override;
  // (x, y, speed) of the car; the reward's weighted distance between the learner's and the expert's motion,
  // each seen from where its part starts (parking_execution.hpp).
  std::vector<TracePoint3> trace_points(const StepSequence& steps) const override;
  // ParkingKitOptions::execution_noise_floor (none with the ready-pool constructor).
  std::optional<NoiseFloor> execution_noise_floor() const override { return noise_floor_; }
  // Alg. 2: quality-aware expertise also left most weak-steering learners quiet (docs/skills.md).
  ExpertiseMode learners_expertise() const override { return ExpertiseMode::Alg2; }
  double execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path, int begin,
                          int end) const override;

  // What each skill does on the expert pool (describe_skill's source; tests find reversing skills here).
  const std::vector<ParkingSkillMotion>& skill_motions() const { return motions_; }
  // Where the pool's and the fresh scenarios' goals lie.
  GoalRegion goal_region() const { return region_; }
  // Why the pool was regenerated ("" when it was read from the file or given).
  const std::string& pool_notice() const { return pool_notice_; }
  // The pool's longest moving drive, in control steps: drives much longer are read in pieces about this long
  // (parking_drive_reading.hpp; also when options.reading reads them in one piece, which does not use it).
  int piece_length() const { return piece_length_; }
  const ParkingDrillProjector& parking_projector() const { return *projector_; }

 private:
  void build(std::vector<ParkingTrial> pool);

  std::shared_ptr<const SkillExtractor> extractor_;
  std::string extractor_notice_;
  std::string pool_notice_;
  GoalRegion region_ = GoalRegion::WholeLot;
  std::optional<NoiseFloor> noise_floor_;
  ParkingDriveReading reading_;
  int piece_length_ = 1;
  std::vector<ExpertDemo> demos_;
  std::vector<ParkingSkillMotion> motions_;
  std::vector<std::string> descriptions_;  // describe_skill's words, distinct among used skills
  std::unique_ptr<ParkingDrillProjector> projector_;
};

}  // namespace sc
