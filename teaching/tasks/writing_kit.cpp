#include "teaching/tasks/writing_kit.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/writing/step_data.hpp"
#include "engine/writing/word_generator.hpp"
#include "engine/writing/writing_score.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/tasks/expert_demos.hpp"
#include "teaching/tasks/writing_execution.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc {
namespace {

constexpr int kMaxWordDraws = 10000;

writing::WritingScenario scenario_of(const Json& doc, const std::string& where) {
  return writing::parse_writing_scenario(JsonView(doc, where));
}

double overlap_reward(const std::vector<writing::TracePoint>& gold, const std::vector<writing::TracePoint>& learner) {
  return non_positive_reward(writing::score_writing(gold, learner).score, 0.0);
}

WordCharacters word_characters(const writing::WordTrajectory& gold) {
  return {gold.word, gold.character_starts, static_cast<int>(gold.steps.size())};
}

}  // namespace

std::vector<std::string> distinct_words(writing::AlphabetKind alphabet, int count, std::uint64_t seed,
                                        const std::vector<std::string>& exclude) {
  Rng rng(seed);
  std::vector<std::string> taken = exclude;
  std::vector<std::string> out;
  for (int draw = 0; draw < kMaxWordDraws && static_cast<int>(out.size()) < count;) {
    std::vector<std::string> words;
    if (alphabet == writing::AlphabetKind::Classic)
      words = writing::generate_classic_words(1, rng);
    else
      words.push_back(writing::generate_balinese_word(rng));
    for (const std::string& w : words) {
      ++draw;
      if (static_cast<int>(out.size()) >= count || std::find(taken.begin(), taken.end(), w) != taken.end()) continue;
      taken.push_back(w);
      out.push_back(w);
    }
  }
  return out;
}

WritingKit::WritingKit(std::shared_ptr<const SkillExtractor> extractor, std::string extractor_notice,
                       const WritingKitOptions& options)
    : extractor_(std::move(extractor)), extractor_notice_(std::move(extractor_notice)), options_(options) {
  if (!extractor_) throw InputError("writing kit", "no skill extractor");
  if (options_.data_dir.empty()) options_.data_dir = writing::omniglot_data_dir();
  const std::vector<std::string> words = distinct_words(options_.alphabet, options_.pool_words, options_.seed, {});
  if (words.empty()) throw InputError("writing kit", "pool_words must be at least 1");
  std::vector<StepSequence> steps;
  std::vector<WordCharacters> characters;
  for (const std::string& word : words) {
    const writing::WritingScenario scenario{word, options_.alphabet, {}};
    writing::WordTrajectory gold = writing::gold_trajectory(scenario, options_.data_dir);
    ExpertDemo d;
    d.scenario = writing::writing_scenario_json(scenario);
    d.trial = writing::writing_trial_json(writing::gold_trial(scenario, gold));
    d.steps = writing_step_sequence(writing::expert_step_data(gold));
    d.reward = 0.0;  // the gold trajectory is the score's reference: overlap 1
    steps.push_back(d.steps);
    characters.push_back(word_characters(gold));
    demos_.push_back(std::move(d));
    golds_.push_back(std::move(gold));
  }
  segment_expert_demos(demos_, *extractor_, kWritingTimeSlices);
  places_ = writing_skill_places(characters, demo_skills(demos_), extractor_->num_skills());
  descriptions_ = describe_writing_places(places_);
  projector_ = std::make_unique<WritingDrillProjector>(std::move(steps));
  hands_ = std::make_unique<WritingHandReferences>(options_.data_dir);
}

StepSequence WritingKit::steps_of(const Json& trial) const {
  return writing_step_sequence(writing::parse_writing_trial(trial, "trial"));
}

double WritingKit::reward_of(const Json& doc) const {
  const writing::WritingTrial trial = writing::parse_writing_trial(doc, "trial");
  for (const writing::WordTrajectory& gold : golds_)
    if (gold.word == trial.scenario.word && trial.scenario.drawers.empty() && gold.alphabet == trial.scenario.alphabet)
      return overlap_reward(gold.points(), trial.points);
  return overlap_reward(writing::gold_trajectory(trial.scenario, options_.data_dir).points(), trial.points);
}

Json WritingKit::expert_trial(const Json& scenario) const {
  return writing::writing_trial_json(writing::gold_trial(scenario_of(scenario, "scenario"), options_.data_dir));
}

std::vector<Json> WritingKit::fresh_scenarios(int count, std::uint64_t seed, const std::vector<Json>& exclude) const {
  std::vector<std::string> taken;
  for (std::size_t i = 0; i < exclude.size(); ++i)
    taken.push_back(scenario_of(exclude[i], "excluded scenario " + std::to_string(i)).word);
  std::vector<Json> out;
  for (const std::string& word : distinct_words(options_.alphabet, count, seed, taken))
    out.push_back(writing::writing_scenario_json({word, options_.alphabet, {}}));
  return out;
}

std::string WritingKit::describe_skill(int skill) const {
  if (skill < 0 || skill >= static_cast<int>(places_.size())) return "unknown skill";
  return descriptions_[static_cast<std::size_t>(skill)];
}

CurriculumConfig WritingKit::curriculum_config() const {
  // Pen steps are infilled to at most 1 px in x and in y, so 30 steps are 30-42 px of pen path: about a
  // third of a 100 px character, a stroke a learner can see and trace. Shorter segments (CompILE's 1-step
  // tails, 20-odd step slivers at character edges) are flicks, not strokes.
  CurriculumConfig config = CurriculumConfig::writing();
  config.min_skill_steps = 30;
  return config;
}

double WritingKit::time_limit_seconds(int expert_steps) const {
  return writing::writing_time_limit_seconds(static_cast<std::size_t>(std::max(expert_steps, 0)));
}

std::string WritingKit::drill_word(const DrillPlan& plan) const {
  std::string word;
  for (const DrillSegment& s : plan.segments) {
    if (s.expert < 0 || s.expert >= static_cast<int>(golds_.size()) || s.end <= s.begin) continue;
    const WordCharacters chars = word_characters(golds_[static_cast<std::size_t>(s.expert)]);
    for (int k = chars.symbol_at(s.begin); k <= chars.symbol_at(s.end - 1); ++k) {
      const char symbol = chars.word[static_cast<std::size_t>(k)];
      if (word.empty() || word.back() != symbol) word.push_back(symbol);
    }
  }
  if (word.size() > static_cast<std::size_t>(writing::kMaxWordSymbols)) word.resize(writing::kMaxWordSymbols);
  return word;
}

Json WritingKit::drill_trial(const PlayableDrill& drill) const {
  writing::WritingTrial trial;
  trial.scenario = {drill_word(drill.plan), options_.alphabet, {}};
  trial.points = WritingDrillProjector::drill_trace(drill);
  for (std::size_t i = 0; i < trial.points.size(); ++i)
    trial.times.push_back(static_cast<double>(i) / writing::kExpertStepsPerSecond);
  trial.source = "drill";
  return writing::writing_trial_json(trial);
}

double WritingKit::drill_attempt_reward(const PlayableDrill& drill, const Json& attempt) const {
  const writing::WritingTrial trial = writing::parse_writing_trial(attempt, "drill attempt");
  return overlap_reward(WritingDrillProjector::drill_trace(drill), trial.points);
}

std::vector<TracePoint3> WritingKit::trace_points(const StepSequence& steps) const {
  return writing_trace_points(steps);
}

double WritingKit::execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                    int begin, int end) const {
  return writing_execution_reward(expert, learner, path, begin, end);
}

std::vector<ExecutionReference> WritingKit::execution_references(const Json& scenario,
                                                                 const StepSequence& expert) const {
  const writing::WritingScenario parsed = scenario_of(scenario, "scenario");
  if (parsed.alphabet != writing::AlphabetKind::Classic) return {};
  return hands_->references(parsed.word, expert);
}

}  // namespace sc
