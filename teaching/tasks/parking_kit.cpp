#include "teaching/tasks/parking_kit.hpp"

#include <algorithm>

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "engine/parking/parking_expert.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/parking_execution.hpp"
#include "teaching/tasks/parking_steps.hpp"

namespace sc {
namespace {

constexpr double kSecondsPerControlStep = 1.0 / parking::kControlHz;
constexpr double kReadingSeconds = 5.0;
constexpr double kHorizonSeconds = parking::kHorizon * kSecondsPerControlStep;

ParkingScenario scenario_of(const Json& scenario, const std::string& where) {
  return parse_parking_scenario(JsonView(scenario, where));
}

}  // namespace

std::filesystem::path default_parking_pool_file(GoalRegion region) {
  return asset_dir() / "experts" /
         (region == GoalRegion::StudyCorner ? "parking_pool_study_corner.json" : "parking_pool.json");
}

int shipped_pool_piece_length() {
  std::vector<StepSequence> drives;
  for (const ParkingTrial& t : load_or_generate_parking_pool(default_parking_pool_file(), {}).trials)
    drives.push_back(parking_step_sequence(t));
  return longest_moving_drive(drives);
}

ParkingKit::ParkingKit(std::shared_ptr<const SkillExtractor> extractor, std::string extractor_notice,
                       const ParkingKitOptions& options)
    : extractor_(std::move(extractor)),
      extractor_notice_(std::move(extractor_notice)),
      region_(options.pool.region),
      noise_floor_(options.execution_noise_floor),
      reading_(options.reading) {
  if (options.pool_file.empty()) {
    build(generate_parking_pool(options.pool));
    return;
  }
  LoadedParkingPool loaded = load_or_generate_parking_pool(options.pool_file, options.pool);
  pool_notice_ = loaded.notice;
  build(std::move(loaded.trials));
}

ParkingKit::ParkingKit(std::shared_ptr<const SkillExtractor> extractor, std::string extractor_notice,
                       std::vector<ParkingTrial> pool, GoalRegion region)
    : extractor_(std::move(extractor)), extractor_notice_(std::move(extractor_notice)), region_(region) {
  build(std::move(pool));
}

void ParkingKit::build(std::vector<ParkingTrial> pool) {
  if (!extractor_) throw InputError("parking kit", "no skill extractor");
  if (pool.empty()) throw InputError("parking kit", "empty expert pool");
  demos_.reserve(pool.size());
  for (const ParkingTrial& t : pool) {
    ExpertDemo d;
    d.scenario = parking_scenario_to_json(t.scenario);
    d.trial = parking_trial_to_json(t);
    d.steps = parking_step_sequence(t);
    d.reward = t.rewards.empty() ? 0.0 : t.rewards.back();
    demos_.push_back(std::move(d));
  }
  const std::vector<StepSequence> steps = demo_steps(demos_);
  piece_length_ = longest_moving_drive(steps);
  extractor_ = parking_drive_reader(std::move(extractor_), piece_length_, reading_);
  segment_expert_demos(demos_, *extractor_, kParkingTimeSlices);
  motions_ = parking_skill_motions(steps, demo_skills(demos_), extractor_->num_skills());
  descriptions_ = describe_parking_motions(motions_);
  projector_ = std::make_unique<ParkingDrillProjector>(std::move(pool));
}

StepSequence ParkingKit::steps_of(const Json& trial) const {
  return parking_step_sequence(parse_parking_trial(trial, "trial"));
}

double ParkingKit::reward_of(const Json& doc) const {
  const ParkingTrial trial = parse_parking_trial(doc, "trial");
  if (!trial.rewards.empty()) return std::min(trial.rewards.back(), 0.0);
  // Not recorded: replay the actions (at the rate they were recorded) and take the last step's reward.
  ParkingSim sim(trial.scenario);
  double last = parking_reward(sim.observation());
  const bool substeps = trial.control_hz != parking::kControlHz;
  const std::size_t per = substeps ? parking::kSubstepsPerAction : 1;
  for (std::size_t i = 0; i + per <= trial.actions.size() && !sim.done(); i += per) {
    last = substeps ? sim.step_substeps({trial.actions[i], trial.actions[i + 1], trial.actions[i + 2]}).reward
                    : sim.step(trial.actions[i]).reward;
  }
  return std::min(last, 0.0);
}

Json ParkingKit::expert_trial(const Json& scenario) const {
  const ParkingScenario wanted = scenario_of(scenario, "scenario");
  for (const ExpertDemo& d : demos_)
    if (scenario_of(d.scenario, "expert pool") == wanted) return d.trial;
  return parking_trial_to_json(ParkingExpert().plan(wanted).to_trial(wanted));
}

std::vector<Json> ParkingKit::fresh_scenarios(int count, std::uint64_t seed, const std::vector<Json>& exclude) const {
  std::vector<ParkingScenario> taken;
  for (std::size_t i = 0; i < exclude.size(); ++i)
    taken.push_back(scenario_of(exclude[i], "excluded scenario " + std::to_string(i)));
  std::vector<Json> out;
  // 3 or 30 spots x continuous headings: collisions with the excluded list are rare, so this ends quickly.
  for (int i = 0; static_cast<int>(out.size()) < count; ++i) {
    const ParkingScenario s = parking_pool_scenario(seed, i, region_);
    if (std::find(taken.begin(), taken.end(), s) != taken.end()) continue;
    taken.push_back(s);
    out.push_back(parking_scenario_to_json(s));
  }
  return out;
}

std::string ParkingKit::describe_skill(int skill) const {
  if (skill < 0 || skill >= static_cast<int>(motions_.size())) return "unknown skill";
  return descriptions_[static_cast<std::size_t>(skill)];
}

CurriculumConfig ParkingKit::curriculum_config() const {
  // A manoeuvre shorter than about a second is over before a learner has seen what the car did (human
  // reaction time alone is ~0.25 s) and cannot be steered on purpose; CompILE's 1-2 step filler segments
  // (reference-facts §3.8) are exactly that.
  CurriculumConfig config = CurriculumConfig::parking();
  config.min_skill_steps = parking::kControlHz;
  return config;
}

double ParkingKit::time_limit_seconds(int expert_steps) const {
  const double t = 2.0 * std::max(expert_steps, 0) * kSecondsPerControlStep + kReadingSeconds;
  return std::min(t, kHorizonSeconds);
}

Json ParkingKit::drill_trial(const PlayableDrill& drill) const {
  return parking_trial_to_json(projector_->drill_trial(drill));
}

double ParkingKit::drill_attempt_reward(const PlayableDrill& drill, const Json& attempt) const {
  const ParkingTrial trial = parse_parking_trial(attempt, "drill attempt");
  if (!(trial.scenario == projector_->drill_scenario(drill.plan)))
    throw InputError("drill attempt", "$.scenario: not the drill's scenario (start and goal differ)");
  return reward_of(attempt);
}

std::vector<TracePoint3> ParkingKit::trace_points(const StepSequence& steps) const {
  return parking_trace_points(steps);
}

double ParkingKit::execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                    int begin, int end) const {
  return parking_execution_reward(expert, learner, path, begin, end);
}

}  // namespace sc
