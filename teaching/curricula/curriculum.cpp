// make_curriculum: each condition is a stream of practice items in its own order; fill_budget takes
// sessions from the stream until the practice budget is reached (rule documented in curriculum.hpp).
#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/error.hpp"
#include "teaching/curricula/adaptive_curriculum.hpp"
#include "teaching/curricula/curriculum.hpp"

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

std::vector<int> distinct_in_order(const std::vector<int>& skills) {
  std::vector<int> out;
  for (int m : skills) {
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  }
  return out;
}

// Skills by number of expert segments, most common first; ties: lower id.
std::vector<std::pair<int, int>> skills_by_frequency(const std::vector<Segmentation>& pool) {
  std::map<int, int> counts;
  for (const auto& seg : pool) {
    for (const auto& s : seg.segments) {
      if (s.length() > 0) ++counts[s.skill];
    }
  }
  std::vector<std::pair<int, int>> out(counts.begin(), counts.end());  // (skill, count), ascending id
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return out;
}

// Skills / Time Heuristic: round-robin over the most common skills, a fresh random segment each time.
ItemStream common_skill_stream(PracticeKind kind, const std::vector<Segmentation>& pool,
                               const CurriculumConfig& config, Rng& rng) {
  auto builder = std::make_shared<DrillBuilder>(pool, config.drills);
  auto ranked = skills_by_frequency(pool);
  if (ranked.size() > static_cast<std::size_t>(config.common_skills)) ranked.resize(static_cast<std::size_t>(config.common_skills));
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
      for (std::size_t i = order->size(); i > 1; --i) std::swap((*order)[i - 1], (*order)[static_cast<std::size_t>(rng.below(i))]);
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

Rng condition_rng(const CurriculumInputs& inputs, StudyCondition condition) {
  return Rng(inputs.seed).fork(static_cast<std::uint64_t>(condition));
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
    case PracticeKind::FullTrajectory: return "full-trajectory";
    case PracticeKind::TimeSlice: return "time-slice";
    case PracticeKind::Skill: return "skill";
    case PracticeKind::Drill: return "drill";
  }
  return "?";
}

int Curriculum::total_steps() const {
  int total = 0;
  for (const auto& item : items) total += item.total_steps();
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
  if (budget_steps < 0) throw InputError("curriculum config", "budget_steps must be >= 0 (0 = default)");
}

int curriculum_budget_steps(const CurriculumInputs& inputs, const CurriculumConfig& config) {
  config.validate();
  if (config.budget_steps > 0) return config.budget_steps;
  require_pool(inputs.expert_skills, "the default budget is the Skills condition's length", StudyCondition::Skills);
  // The Skills condition's first round, drawn with the same random stream as make_curriculum(Skills).
  Rng rng = condition_rng(inputs, StudyCondition::Skills);
  const ItemStream next = common_skill_stream(PracticeKind::Skill, inputs.expert_skills, config, rng);
  const std::size_t skills = std::min(skills_by_frequency(inputs.expert_skills).size(),
                                      static_cast<std::size_t>(config.common_skills));
  int budget = 0;
  for (std::size_t i = 0; i < skills; ++i) budget += next()->total_steps();
  return budget;
}

Curriculum individualized_drill_curriculum(StudyCondition condition, const ExpertiseEstimate& diagnosis,
                                           int budget, const CurriculumInputs& inputs,
                                           const CurriculumConfig& config, Rng& rng) {
  require_pool(inputs.expert_skills, "drills are cut from them", condition);
  if (diagnosis.ranking.empty()) {
    throw InputError(std::string(condition_name(condition)) + " curriculum",
                     "the diagnosis has no skills to target (no pre-test trials with expert skills)");
  }
  const DrillBuilder builder(inputs.expert_skills, config.drills);
  Curriculum out{condition, budget, {}};
  out.items = fill_budget(drill_stream([&] { return builder.individualized(diagnosis, rng); },
                                       config.sessions_per_drill),
                          budget);
  return out;
}

Curriculum make_curriculum(StudyCondition condition, const CurriculumInputs& inputs, const CurriculumConfig& config) {
  const int budget = curriculum_budget_steps(inputs, config);
  Rng rng = condition_rng(inputs, condition);
  Curriculum out{condition, budget, {}};
  switch (condition) {
    case StudyCondition::FullTrajectory:
      require_pool(inputs.expert_skills, "whole trajectories are played", condition);
      out.items = fill_budget(full_trajectory_stream(inputs.expert_skills, config, rng), budget);
      break;
    case StudyCondition::TimeHeuristic:
      require_pool(inputs.expert_time_slices, "expert_time_slices is empty", condition);
      out.items = fill_budget(common_skill_stream(PracticeKind::TimeSlice, inputs.expert_time_slices, config, rng), budget);
      break;
    case StudyCondition::Skills:
      out.items = fill_budget(common_skill_stream(PracticeKind::Skill, inputs.expert_skills, config, rng), budget);
      break;
    case StudyCondition::Drills: {
      require_pool(inputs.expert_skills, "drills are cut from them", condition);
      const DrillBuilder builder(inputs.expert_skills, config.drills);
      const int batch = static_cast<int>(builder.offline_ngrams().size());
      out.items = fill_budget(drill_stream([&] { return builder.random_drills(batch, rng); }, config.sessions_per_drill),
                              budget);
      break;
    }
    case StudyCondition::IndDrills:
      return individualized_drill_curriculum(condition, inputs.pretest, budget, inputs, config, rng);
    case StudyCondition::Adaptive:
      return first_adaptive_round(inputs, config).practice;
  }
  return out;
}

}  // namespace sc
