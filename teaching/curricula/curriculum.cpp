// make_curriculum: each condition is a stream of practice items in its own order; fill_budget takes
// sessions from the stream until the practice budget is reached (rule documented in curriculum.hpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/error.hpp"
#include "teaching/curricula/adaptive_curriculum.hpp"
#include "teaching/curricula/curriculum.hpp"
#include "teaching/curricula/teachable_skills.hpp"

namespace sc {
namespace {

using ItemStream = std::function<std::optional<PracticeItem>()>;  // nullopt: no material at all

std::vector<PracticeItem> fill_budget(const ItemStream& next, int budget) {
  std::vector<PracticeItem> items;
  int total = 0;
  int empty_items = 0;
  bool stop = false;
  while (!stop && total < budget) {
    std::optional<PracticeItem> item = next();
    if (!item) break;
    const int len = item->steps();
    if (len <= 0) {
      if (++empty_items > 1000) break;  // a stream of empty material would never fill the budget
      continue;
    }
    int sessions = 0;
    while (sessions < item->sessions && total < budget) {
      // Keep the crossing session only if it lands at least as close to the budget as stopping here.
      if (total > 0 && total + len - budget > budget - total) {
        stop = true;
        break;
      }
      total += len;
      ++sessions;
    }
    if (sessions > 0) {
      item->sessions = sessions;
      items.push_back(std::move(*item));
    }
  }
  return items;
}

// The default budget's rule (curriculum.hpp): land within [lo, hi], skipping items whose next session would
// overshoot. Coarse material (whole trajectories all longer than the gap left) can leave no candidate that
// fits; after kStuck misses in a row the last session is given back, so that material of another length can
// land in the window. Bounded, because a stream never runs dry on its own.
std::vector<PracticeItem> fill_window(const ItemStream& next, int budget, double tolerance) {
  constexpr int kMaxCandidates = 2000;
  constexpr int kStuck = 200;  // more than a pass over a 100-demo expert pool
  const int lo = static_cast<int>(std::ceil(budget * (1.0 - tolerance)));
  const int hi = static_cast<int>(std::floor(budget * (1.0 + tolerance)));
  std::vector<PracticeItem> items;
  int total = 0;
  int misses = 0;
  for (int tries = 0; tries < kMaxCandidates && total < lo; ++tries) {
    std::optional<PracticeItem> item = next();
    if (!item) break;
    const int len = item->steps();
    int sessions = 0;
    while (len > 0 && sessions < item->sessions && total < lo && total + len <= hi) {
      total += len;
      ++sessions;
    }
    if (sessions > 0) {
      item->sessions = sessions;
      items.push_back(std::move(*item));
      misses = 0;
    } else if (++misses >= kStuck && !items.empty()) {
      total -= items.back().steps();
      if (--items.back().sessions == 0) items.pop_back();
      misses = 0;
    }
  }
  return items;
}

std::vector<int> distinct_in_order(const std::vector<int>& skills) {
  std::vector<int> out;
  for (int m : skills) {
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  }
  return out;
}

// Drills and skills are cut from segments at least min_skill_steps long where the skill has them.
DrillConfig teaching_drills(const CurriculumConfig& config) {
  DrillConfig d = config.drills;
  d.min_segment_length = std::max(d.min_segment_length, config.min_skill_steps);
  return d;
}

// Skills: the most common teachable skills. Time Heuristic: slice indices drawn at random, because every
// slice index occurs once per trajectory (by frequency the first slices would always win).
std::vector<std::pair<int, int>> practised_skills(PracticeKind kind, const std::vector<Segmentation>& pool,
                                                  const CurriculumConfig& config, Rng& rng) {
  auto ranked = teachable_by_frequency(pool, config.min_skill_steps);
  if (kind == PracticeKind::TimeSlice) {
    for (std::size_t i = ranked.size(); i > 1; --i)
      std::swap(ranked[i - 1], ranked[static_cast<std::size_t>(rng.below(i))]);
  }
  if (ranked.size() > static_cast<std::size_t>(config.common_skills))
    ranked.resize(static_cast<std::size_t>(config.common_skills));
  return ranked;
}

// Skills / Time Heuristic: round-robin over the most common skills, a fresh random segment each time.
ItemStream common_skill_stream(PracticeKind kind, const std::vector<Segmentation>& pool, const CurriculumConfig& config,
                               Rng& rng) {
  auto builder = std::make_shared<DrillBuilder>(pool, teaching_drills(config));
  const auto ranked = practised_skills(kind, pool, config, rng);
  auto next_index = std::make_shared<std::size_t>(0);
  return [=, &rng]() -> std::optional<PracticeItem> {
    if (ranked.empty()) return std::nullopt;
    const auto [skill, count] = ranked[(*next_index)++ % ranked.size()];
    PracticeItem item;
    item.kind = kind;
    item.target_skills = {skill};
    item.material.target_skill = skill;
    item.material.ngram = {skill};
    item.material.ngram_count = count;
    item.material.segments = {builder->random_segment(skill, rng)};
    item.sessions = config.sessions_per_skill;
    return item;
  };
}

ItemStream full_trajectory_stream(const std::vector<Segmentation>& pool, const CurriculumConfig& config, Rng& rng) {
  std::vector<int> usable;
  for (std::size_t i = 0; i < pool.size(); ++i) {
    if (!pool[i].segments.empty()) usable.push_back(static_cast<int>(i));
  }
  auto order = std::make_shared<std::vector<int>>();
  return [=, &pool, &rng]() -> std::optional<PracticeItem> {
    if (usable.empty()) return std::nullopt;
    if (order->empty()) {  // a new pass: distinct trajectories in a seeded random order
      *order = usable;
      for (std::size_t i = order->size(); i > 1; --i)
        std::swap((*order)[i - 1], (*order)[static_cast<std::size_t>(rng.below(i))]);
      std::reverse(order->begin(), order->end());  // consumed from the back
    }
    const int e = order->back();
    order->pop_back();
    const Segmentation& seg = pool[static_cast<std::size_t>(e)];
    PracticeItem item;
    item.kind = PracticeKind::FullTrajectory;
    item.target_skills = distinct_in_order(seg.skills());
    item.material.ngram = seg.skills();
    for (const auto& s : seg.segments) item.material.segments.push_back({s.skill, e, s.begin, s.end});
    item.sessions = config.sessions_per_trajectory;
    return item;
  };
}

// Drills and Ind. Drills: batches of plans from `make_batch`, consumed in order, refilled when used up.
ItemStream drill_stream(std::function<std::vector<DrillPlan>()> make_batch, int sessions) {
  auto batch = std::make_shared<std::vector<DrillPlan>>();
  auto next = std::make_shared<std::size_t>(0);
  return [=]() -> std::optional<PracticeItem> {
    if (*next >= batch->size()) {
      *batch = make_batch();
      *next = 0;
      if (batch->empty()) return std::nullopt;
    }
    PracticeItem item;
    item.kind = PracticeKind::Drill;
    item.material = (*batch)[(*next)++];
    item.target_skills = item.material.target_skill >= 0 ? std::vector<int>{item.material.target_skill}
                                                         : distinct_in_order(item.material.ngram);
    item.sessions = sessions;
    return item;
  };
}

void require_pool(const std::vector<Segmentation>& pool, std::string_view what, StudyCondition condition) {
  bool any = false;
  for (const auto& seg : pool) any = any || !seg.segments.empty();
  if (!any) {
    throw InputError(std::string(condition_name(condition)) + " curriculum",
                     "no segmented expert trajectories (" + std::string(what) + ")");
  }
}

}  // namespace

std::string_view practice_kind_key(PracticeKind kind) {
  switch (kind) {
    case PracticeKind::FullTrajectory:
      return "full-trajectory";
    case PracticeKind::TimeSlice:
      return "time-slice";
    case PracticeKind::Skill:
      return "skill";
    case PracticeKind::Drill:
      return "drill";
  }
  return "?";
}

int Curriculum::total_steps() const {
  int total = 0;
  for (const auto& item : items) total += item.total_steps();
  return total;
}

int Curriculum::trials() const {
  int total = 0;
  for (const auto& item : items) total += item.sessions;
  return total;
}

CurriculumConfig CurriculumConfig::parking() { return CurriculumConfig{}; }

CurriculumConfig CurriculumConfig::writing() {
  CurriculumConfig c;
  c.drills = DrillConfig::writing();
  return c;
}

void CurriculumConfig::validate() const {
  drills.validate();
  auto positive = [](int v, const char* name) {
    if (v < 1) throw InputError("curriculum config", std::string(name) + " must be >= 1, got " + std::to_string(v));
  };
  positive(common_skills, "common_skills");
  positive(sessions_per_skill, "sessions_per_skill");
  positive(sessions_per_trajectory, "sessions_per_trajectory");
  positive(sessions_per_drill, "sessions_per_drill");
  positive(adaptive_rounds, "adaptive_rounds");
  positive(weak_skills, "weak_skills");
  positive(drills_per_weak_skill, "drills_per_weak_skill");
  positive(min_skill_steps, "min_skill_steps");
  if (budget_steps < 0) throw InputError("curriculum config", "budget_steps must be >= 0 (0 = default)");
  if (!(budget_tolerance >= 0.0 && budget_tolerance <= 0.5))
    throw InputError("curriculum config", "budget_tolerance must be within 0..0.5");
}

Rng curriculum_rng(const CurriculumInputs& inputs, StudyCondition condition) {
  return Rng(inputs.seed).fork(static_cast<std::uint64_t>(condition));
}

int curriculum_budget_steps(const CurriculumInputs& inputs, const CurriculumConfig& config) {
  config.validate();
  if (config.budget_steps > 0) return config.budget_steps;
  Rng rng = curriculum_rng(inputs, StudyCondition::IndDrills);  // the same draws as make_curriculum(IndDrills)
  return weak_skill_round(StudyCondition::IndDrills, inputs.pretest, inputs, config, rng).total_steps();
}

std::string budget_reference(const CurriculumConfig& config) {
  if (config.budget_steps > 0) return "set to " + std::to_string(config.budget_steps) + " steps";
  return "Ind. Drills, " + std::to_string(config.drills_per_weak_skill) + " drills for each of the " +
         std::to_string(config.weak_skills) + " weakest skills";
}

Curriculum weak_skill_round(StudyCondition condition, const ExpertiseEstimate& diagnosis,
                            const CurriculumInputs& inputs, const CurriculumConfig& config, Rng& rng) {
  config.validate();
  require_pool(inputs.expert_skills, "drills are cut from them", condition);
  DrillConfig drills = teaching_drills(config);
  drills.drills_per_target = config.drills_per_weak_skill;
  drills.distinct_ngrams = true;  // "unique drills"
  const DrillBuilder builder(inputs.expert_skills, drills);
  std::vector<int> targets;
  for (int m : teachable_ranking(diagnosis, inputs.expert_skills, config.min_skill_steps)) {
    if (static_cast<int>(targets.size()) >= config.weak_skills) break;
    if (!builder.ngrams().most_frequent_containing(m, 1).empty()) targets.push_back(m);
  }
  if (targets.empty()) {
    throw InputError(std::string(condition_name(condition)) + " curriculum",
                     "the diagnosis has no teachable skill to target (no pre-test trials with expert skills)");
  }
  Curriculum out{condition, 0, {}};
  for (DrillPlan& plan : builder.for_targets(targets, rng)) {
    PracticeItem item;
    item.kind = PracticeKind::Drill;
    item.target_skills = {plan.target_skill};
    item.material = std::move(plan);
    item.sessions = config.sessions_per_drill;
    out.items.push_back(std::move(item));
  }
  out.budget_steps = out.total_steps();
  return out;
}

Curriculum individualized_drill_curriculum(StudyCondition condition, const ExpertiseEstimate& diagnosis, int budget,
                                           const CurriculumInputs& inputs, const CurriculumConfig& config, Rng& rng) {
  require_pool(inputs.expert_skills, "drills are cut from them", condition);
  if (diagnosis.ranking.empty()) {
    throw InputError(std::string(condition_name(condition)) + " curriculum",
                     "the diagnosis has no skills to target (no pre-test trials with expert skills)");
  }
  const DrillBuilder builder(inputs.expert_skills, config.drills);
  Curriculum out{condition, budget, {}};
  out.items = fill_budget(
      drill_stream([&] { return builder.individualized(diagnosis, rng); }, config.sessions_per_drill), budget);
  return out;
}

namespace {

// Random drills, without those made only of skills too brief to practise (teachable_skills.hpp).
std::vector<DrillPlan> teachable_random_drills(const DrillBuilder& builder, const std::vector<Segmentation>& pool,
                                               int min_steps, Rng& rng) {
  std::vector<DrillPlan> out;
  for (DrillPlan& plan : builder.random_drills(static_cast<int>(builder.offline_ngrams().size()), rng)) {
    const bool any =
        std::any_of(plan.ngram.begin(), plan.ngram.end(), [&](int m) { return is_teachable(m, pool, min_steps); });
    if (any) out.push_back(std::move(plan));
  }
  return out;
}

ItemStream condition_stream(StudyCondition condition, const CurriculumInputs& inputs, const CurriculumConfig& config,
                            const std::shared_ptr<DrillBuilder>& builder, Rng& rng) {
  switch (condition) {
    case StudyCondition::FullTrajectory:
      require_pool(inputs.expert_skills, "whole trajectories are played", condition);
      return full_trajectory_stream(inputs.expert_skills, config, rng);
    case StudyCondition::TimeHeuristic:
      require_pool(inputs.expert_time_slices, "expert_time_slices is empty", condition);
      return common_skill_stream(PracticeKind::TimeSlice, inputs.expert_time_slices, config, rng);
    case StudyCondition::Skills:
      require_pool(inputs.expert_skills, "skills are cut from them", condition);
      return common_skill_stream(PracticeKind::Skill, inputs.expert_skills, config, rng);
    default: {  // Drills
      require_pool(inputs.expert_skills, "drills are cut from them", condition);
      const int min_steps = config.min_skill_steps;
      const std::vector<Segmentation>& pool = inputs.expert_skills;
      return drill_stream(
          [builder, &pool, min_steps, &rng] { return teachable_random_drills(*builder, pool, min_steps, rng); },
          config.sessions_per_drill);
    }
  }
}

}  // namespace

Curriculum make_curriculum(StudyCondition condition, const CurriculumInputs& inputs, const CurriculumConfig& config) {
  config.validate();
  Rng rng = curriculum_rng(inputs, condition);
  const bool fixed_budget = config.budget_steps > 0;
  if (condition == StudyCondition::Adaptive) return first_adaptive_round(inputs, config).practice;
  if (condition == StudyCondition::IndDrills) {
    if (!fixed_budget) return weak_skill_round(condition, inputs.pretest, inputs, config, rng);
    return individualized_drill_curriculum(condition, inputs.pretest, config.budget_steps, inputs, config, rng);
  }
  const int budget = curriculum_budget_steps(inputs, config);
  std::shared_ptr<DrillBuilder> builder;
  if (condition == StudyCondition::Drills) {
    require_pool(inputs.expert_skills, "drills are cut from them", condition);
    builder = std::make_shared<DrillBuilder>(inputs.expert_skills, teaching_drills(config));
  }
  const ItemStream stream = condition_stream(condition, inputs, config, builder, rng);
  Curriculum out{condition, budget, {}};
  out.items = fixed_budget ? fill_budget(stream, budget) : fill_window(stream, budget, config.budget_tolerance);
  return out;
}

std::map<int, int> practice_trials_per_skill(const Curriculum& curriculum, const std::vector<int>& played) {
  std::map<int, int> out;
  for (int index : played) {
    if (index < 0 || index >= static_cast<int>(curriculum.items.size()))
      throw InputError("practice", "item " + std::to_string(index) + " is not in the round's curriculum");
    const PracticeItem& item = curriculum.items[static_cast<std::size_t>(index)];
    if (item.kind != PracticeKind::Drill && item.kind != PracticeKind::Skill) continue;
    for (int m : item.target_skills) ++out[m];
  }
  return out;
}

}  // namespace sc
