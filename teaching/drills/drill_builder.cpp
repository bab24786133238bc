#include "teaching/drills/drill_builder.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "engine/core/error.hpp"

namespace sc {
namespace {

void require_positive(int value, const char* name) {
  if (value < 1) throw InputError("drill config", std::string(name) + " must be >= 1, got " + std::to_string(value));
}

const std::vector<Segmentation>& checked_pool(const std::vector<Segmentation>& pool) {
  for (std::size_t i = 0; i < pool.size(); ++i) {
    for (const auto& s : pool[i].segments) {
      if (s.skill < 0) {
        throw InputError("expert segmentation " + std::to_string(i), "negative skill id " + std::to_string(s.skill));
      }
    }
  }
  return pool;
}

}  // namespace

void DrillConfig::validate() const {
  require_positive(ngram_length, "n (ngram_length)");
  require_positive(repetitions, "N_rep (repetitions)");
  require_positive(num_targets, "N_target (num_targets)");
  require_positive(drills_per_target, "N_drills (drills_per_target)");
  require_positive(min_segment_length, "min_segment_length");
}

DrillBuilder::DrillBuilder(std::vector<Segmentation> expert_pool, DrillConfig config)
    : pool_(std::move(expert_pool)),
      config_((config.validate(), config)),
      ngrams_(checked_pool(pool_), config_.ngram_length) {}

std::vector<DrillSegment> DrillBuilder::segments_of(int skill) const {
  std::vector<DrillSegment> out;
  for (std::size_t i = 0; i < pool_.size(); ++i) {
    for (const auto& s : pool_[i].segments) {
      if (s.skill == skill && s.length() > 0) out.push_back({s.skill, static_cast<int>(i), s.begin, s.end});
    }
  }
  return out;
}

DrillSegment DrillBuilder::random_segment(int skill, Rng& rng) const {
  const std::vector<DrillSegment> all = segments_of(skill);
  if (all.empty()) throw InputError("drill", "skill " + std::to_string(skill) + " has no expert segment");
  std::vector<DrillSegment> long_enough;
  for (const auto& s : all) {
    if (s.length() >= config_.min_segment_length) long_enough.push_back(s);
  }
  const auto& choices = long_enough.empty() ? all : long_enough;
  return choices[static_cast<std::size_t>(rng.below(choices.size()))];
}

DrillPlan DrillBuilder::project(const SkillNgram& gram, int target_skill, Rng& rng) const {
  DrillPlan plan;
  plan.target_skill = target_skill;
  plan.ngram = gram.skills;
  plan.ngram_count = gram.count;
  plan.repetitions = config_.repetitions;
  std::vector<DrillSegment> once;
  for (int m : gram.skills) once.push_back(random_segment(m, rng));
  for (int r = 0; r < config_.repetitions; ++r) plan.segments.insert(plan.segments.end(), once.begin(), once.end());
  return plan;
}

std::vector<DrillPlan> DrillBuilder::for_targets(const std::vector<int>& targets, Rng& rng) const {
  std::vector<DrillPlan> out;
  std::vector<std::vector<int>> used;
  for (int target : targets) {
    std::vector<SkillNgram> grams;
    const std::vector<SkillNgram> all = ngrams_.most_frequent_containing(target, config_.drills_per_target);
    if (config_.distinct_ngrams) {
      grams = ngrams_.most_frequent_containing(target, config_.drills_per_target, used);
      // Fewer unused n-grams than drills (a small lot uses few skill sequences): the most frequent ones
      // again, each cut from freshly drawn expert segments, so every target still gets N_drills drills.
      for (std::size_t i = 0; grams.size() < static_cast<std::size_t>(config_.drills_per_target) && !all.empty(); ++i)
        grams.push_back(all[i % all.size()]);
    }
    if (grams.empty()) grams = all;
    for (const auto& g : grams) {
      out.push_back(project(g, target, rng));
      used.push_back(g.skills);
    }
  }
  return out;
}

std::vector<DrillPlan> DrillBuilder::individualized(const ExpertiseEstimate& estimate, Rng& rng) const {
  const std::size_t n = std::min(estimate.ranking.size(), static_cast<std::size_t>(config_.num_targets));
  return for_targets(std::vector<int>(estimate.ranking.begin(), estimate.ranking.begin() + static_cast<long>(n)), rng);
}

std::vector<SkillNgram> DrillBuilder::offline_ngrams() const {
  std::vector<int> skills;
  for (const auto& seg : pool_) {
    for (const auto& s : seg.segments) skills.push_back(s.skill);
  }
  std::sort(skills.begin(), skills.end());
  skills.erase(std::unique(skills.begin(), skills.end()), skills.end());
  std::vector<SkillNgram> out;
  for (int m : skills) {
    for (const auto& g : ngrams_.most_frequent_containing(m, config_.drills_per_target)) {
      if (std::find(out.begin(), out.end(), g) == out.end()) out.push_back(g);
    }
  }
  return out;
}

std::vector<DrillPlan> DrillBuilder::random_drills(int count, Rng& rng) const {
  if (count < 0) throw InputError("drills", "the number of random drills must be >= 0");
  const std::vector<SkillNgram> offline = offline_ngrams();
  std::vector<DrillPlan> out;
  if (offline.empty()) return out;
  std::vector<std::size_t> order;
  while (static_cast<int>(out.size()) < count) {
    if (order.empty()) {  // (re)fill and shuffle (Fisher-Yates with our portable Rng)
      for (std::size_t i = 0; i < offline.size(); ++i) order.push_back(i);
      for (std::size_t i = order.size(); i > 1; --i)
        std::swap(order[i - 1], order[static_cast<std::size_t>(rng.below(i))]);
    }
    const std::size_t pick = order.back();
    order.pop_back();
    out.push_back(project(offline[pick], -1, rng));
  }
  return out;
}

}  // namespace sc
