#include "tests/sessions/toy_task_kit.hpp"

#include <algorithm>

#include "engine/core/rng.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"

namespace sc::test {
namespace {

class RunExtractor final : public SkillExtractor {
 public:
  Segmentation extract(const StepSequence& t) const override {
    Segmentation s;
    for (int i = 0; i < t.length(); ++i) {
      const int g = static_cast<int>(t.actions[static_cast<std::size_t>(i)]);
      if (!s.segments.empty() && s.segments.back().skill == g)
        s.segments.back().end = i + 1;
      else
        s.segments.push_back({g, i, i + 1});
    }
    return s;
  }
  int num_skills() const override { return kToySkills; }
  std::string name() const override { return "toy-runs"; }
};

StepSequence steps_from(const std::vector<int>& gestures) {
  StepSequence steps;
  steps.state_dim = 1;
  steps.action_dim = 1;
  float x = 0;
  for (int g : gestures) {
    steps.states.push_back(x);
    steps.actions.push_back(static_cast<float>(g));
    x += static_cast<float>(g);
  }
  return steps;
}

class ToyProjector final : public DrillProjector {
 public:
  explicit ToyProjector(const std::vector<ExpertDemo>& pool) : pool_(pool) {}
  PlayableDrill project(const DrillPlan& plan) const override {
    std::vector<StepSequence> experts;
    for (const auto& d : pool_) experts.push_back(d.steps);
    PlayableDrill drill;
    drill.plan = plan;
    drill.steps = concatenate_expert_steps(plan, experts);
    double x = 0;
    for (int i = 0; i < drill.steps.length(); ++i) {
      drill.ghost_path.push_back({x, 0.0});
      x += drill.steps.actions[static_cast<std::size_t>(i)];
    }
    drill.ghost_path.push_back({x, 0.0});
    drill.final_state = {static_cast<float>(x)};
    drill.segment_starts = plan.segment_starts();
    drill.success = true;
    return drill;
  }

 private:
  const std::vector<ExpertDemo>& pool_;
};

const RunExtractor& run_extractor() {
  static const RunExtractor extractor;  // stateless
  return extractor;
}

}  // namespace

std::vector<int> toy_expert_gestures(int id) {
  // Four runs in a scenario-dependent order and length: every scenario shows 3 or 4 skills.
  std::vector<int> out;
  for (int k = 0; k < 4; ++k) {
    const int skill = (id + k * (1 + id % 3)) % kToySkills;
    const int length = 2 + (id + k) % 3;
    if (k == 3 && id % 2 == 0) break;
    for (int i = 0; i < length; ++i) out.push_back(skill);
  }
  return out;
}

std::vector<int> toy_learner_gestures(int id, int forget, int instead) {
  std::vector<int> g = toy_expert_gestures(id);
  for (int& v : g)
    if (v == forget) v = instead;
  return g;
}

Json toy_trial(int id, const std::vector<int>& gestures) {
  return Json{{"task", "toy"}, {"scenario", {{"id", id}}}, {"actions", gestures}};
}

Json toy_practice_trial(const PlayableDrill& drill, int forget, int instead) {
  std::vector<int> reference, mine;
  for (float a : drill.steps.actions) {
    reference.push_back(static_cast<int>(a));
    mine.push_back(static_cast<int>(a) == forget ? instead : static_cast<int>(a));
  }
  return Json{{"task", "toy"}, {"scenario", {{"id", -1}}}, {"actions", mine}, {"reference", reference}};
}

ToyTaskKit::ToyTaskKit(int pool_size, ExpertiseMode expertise) : expertise_(expertise) {
  for (int id = 0; id < pool_size; ++id) {
    ExpertDemo demo;
    demo.scenario = Json{{"id", id}};
    demo.trial = toy_trial(id, toy_expert_gestures(id));
    demo.steps = steps_from(toy_expert_gestures(id));
    demo.skills = run_extractor().extract(demo.steps);
    demo.time_slices = TimeHeuristicExtractor(kToySkills).extract(demo.steps);
    pool_.push_back(std::move(demo));
  }
  projector_ = std::make_unique<ToyProjector>(pool_);
}

const SkillExtractor& ToyTaskKit::extractor() const { return run_extractor(); }
const DrillProjector& ToyTaskKit::projector() const { return *projector_; }

CurriculumConfig ToyTaskKit::curriculum_config() const {
  CurriculumConfig config;
  config.drills.ngram_length = 2;
  config.drills.num_targets = 2;
  return config;
}

StepSequence ToyTaskKit::steps_of(const Json& trial) const {
  return steps_from(trial.at("actions").get<std::vector<int>>());
}

double ToyTaskKit::reward_of(const Json& trial) const {
  const std::vector<int> mine = trial.at("actions").get<std::vector<int>>();
  // Practice trials carry the drill's own gestures as "reference"; tests compare with the scenario's expert.
  const std::vector<int> expert = trial.contains("reference")
                                      ? trial.at("reference").get<std::vector<int>>()
                                      : toy_expert_gestures(trial.at("scenario").at("id").get<int>());
  if (mine.size() != expert.size()) return -1.0;
  int wrong = 0;
  for (std::size_t i = 0; i < mine.size(); ++i) wrong += mine[i] != expert[i] ? 1 : 0;
  return -static_cast<double>(wrong) / static_cast<double>(std::max<std::size_t>(1, mine.size()));
}

Json ToyTaskKit::expert_trial(const Json& scenario) const {
  const int id = scenario.at("id").get<int>();
  return toy_trial(id, toy_expert_gestures(id));
}

std::vector<Json> ToyTaskKit::fresh_scenarios(int count, std::uint64_t seed, const std::vector<Json>& exclude) const {
  ++fresh_calls;
  Rng rng(seed);
  std::vector<Json> out;
  while (static_cast<int>(out.size()) < count) {
    const Json candidate{{"id", 100 + static_cast<int>(rng.below(1000))}};
    if (std::find(exclude.begin(), exclude.end(), candidate) == exclude.end() &&
        std::find(out.begin(), out.end(), candidate) == out.end())
      out.push_back(candidate);
  }
  return out;
}

Json ToyTaskKit::drill_trial(const PlayableDrill& drill) const { return toy_practice_trial(drill, -1, -1); }

double ToyTaskKit::drill_attempt_reward(const PlayableDrill& drill, const Json& attempt) const {
  Json scored = attempt;
  scored["reference"] = toy_practice_trial(drill, -1, -1).at("reference");
  return reward_of(scored);
}

std::vector<TracePoint3> ToyTaskKit::trace_points(const StepSequence& steps) const {
  std::vector<TracePoint3> out;
  for (int t = 0; t < steps.length(); ++t)
    out.push_back({steps.states[static_cast<std::size_t>(t * steps.state_dim)], 0.0, 0.0});
  return out;
}

double ToyTaskKit::execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                    int begin, int end) const {
  const std::vector<TracePoint3> e = trace_points(expert), l = trace_points(learner);
  double differ = 0.0;
  int pairs = 0;
  for (const auto& [i, j] : path) {
    if (i < begin || i >= end) continue;
    differ += e[static_cast<std::size_t>(i)][0] != l[static_cast<std::size_t>(j)][0];
    ++pairs;
  }
  return pairs > 0 ? -differ / pairs : 0.0;
}

std::string ToyTaskKit::describe_skill(int skill) const { return "gesture " + std::to_string(skill); }

std::vector<ExecutionReference> ToyTaskKit::execution_references(const Json&, const StepSequence& expert) const {
  if (!give_references) return {};
  ExecutionReference r{"the double-length hand", expert, {}};
  for (float& v : r.steps.states) v *= 2.0f;
  for (int t = 0; t < expert.length(); ++t) r.from_expert.push_back({t, t});
  return {r};
}

}  // namespace sc::test
