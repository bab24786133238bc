#pragma once
// A small deterministic TaskKit for the orchestrator's tests (the real parking/writing kits are slow to
// build and belong to teaching/tasks). The toy task: a 1-D "car" whose action each step is an integer
// gesture 0..3; a skill is a run of equal gestures (the extractor reads them back exactly), the ghost path
// is the running sum. Expert k of the pool plays a fixed gesture pattern; the learner's reward is minus
// the fraction of steps that differ from the expert's, so a learner who never shows a skill is penalised.
#include <memory>
#include <vector>

#include "teaching/sessions/task_kit.hpp"

namespace sc::test {

inline constexpr int kToySkills = 4;

// {"task":"toy","scenario":{"id":k},"actions":[...]} documents.
Json toy_trial(int scenario_id, const std::vector<int>& gestures);
std::vector<int> toy_expert_gestures(int scenario_id);
// The expert's gestures with every gesture `forget` replaced by `instead` (a learner missing a skill).
std::vector<int> toy_learner_gestures(int scenario_id, int forget, int instead);
// A practice attempt at a drill: its expert gestures with `forget` replaced (reference = the drill's own).
Json toy_practice_trial(const PlayableDrill& drill, int forget, int instead);

class ToyTaskKit final : public TaskKit {
 public:
  explicit ToyTaskKit(int pool_size = 8, ExpertiseMode expertise = ExpertiseMode::Alg2);
  std::string task() const override { return "toy"; }
  const SkillExtractor& extractor() const override;
  std::string extractor_notice() const override { return {}; }
  const std::vector<ExpertDemo>& expert_pool() const override { return pool_; }
  const DrillProjector& projector() const override;
  CurriculumConfig curriculum_config() const override;
  StepSequence steps_of(const Json& trial) const override;
  double reward_of(const Json& trial) const override;
  Json expert_trial(const Json& scenario) const override;
  std::vector<Json> fresh_scenarios(int count, std::uint64_t seed, const std::vector<Json>& exclude) const override;
  std::string describe_skill(int skill) const override;
  double time_limit_seconds(int expert_steps) const override { return 0.2 * expert_steps * 2.0; }
  Json drill_trial(const PlayableDrill& drill) const override;
  double drill_attempt_reward(const PlayableDrill& drill, const Json& attempt) const override;
  // The position is the 1-D car's (state 0); an aligned step's execution error is 1 when the positions differ.
  std::vector<TracePoint3> trace_points(const StepSequence& steps) const override;
  std::optional<NoiseFloor> execution_noise_floor() const override { return std::nullopt; }
  ExpertiseMode learners_expertise() const override { return expertise_; }
  double execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path, int begin,
                          int end) const override;
  // With `give_references`: one reference, "the double-length hand", the expert's positions doubled, step by step.
  std::vector<ExecutionReference> execution_references(const Json& scenario, const StepSequence& expert) const override;
  bool give_references = false;

  mutable int fresh_calls = 0;  // how often fresh_scenarios ran (tests check caching)

 private:
  ExpertiseMode expertise_;
  std::vector<ExpertDemo> pool_;
  std::unique_ptr<DrillProjector> projector_;
};

}  // namespace sc::test
