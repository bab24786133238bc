#include "teaching/curricula/curriculum.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/curricula/adaptive_curriculum.hpp"

namespace sc {
namespace {

// A parking-like pool: 40 experts, 2-4 skills each from 10 skills with uneven frequencies, 3-10 steps each.
struct Pool {
  std::vector<Segmentation> skills;
  std::vector<Segmentation> time_slices;
  int longest_trajectory = 0;
  int longest_segment = 0;
  int longest_slice = 0;
};

Pool make_pool() {
  Pool p;
  Rng rng(2024);
  for (int e = 0; e < 40; ++e) {
    Segmentation seg;
    int t = 0;
    const int parts = 2 + static_cast<int>(rng.below(3));
    for (int k = 0; k < parts; ++k) {
      const int skill = static_cast<int>(rng.below(4) + rng.below(7));  // 0..9, middle ids more common
      const int len = 3 + static_cast<int>(rng.below(8));
      seg.segments.push_back({skill, t, t + len});
      p.longest_segment = std::max(p.longest_segment, len);
      t += len;
    }
    p.longest_trajectory = std::max(p.longest_trajectory, t);
    p.skills.push_back(seg);
    // The time heuristic: three (nearly) equal slices, slice index = "skill" (as TimeHeuristicExtractor).
    p.time_slices.push_back(Segmentation{{{0, 0, t / 3}, {1, t / 3, 2 * t / 3}, {2, 2 * t / 3, t}}});
    for (const auto& s : p.time_slices.back().segments) p.longest_slice = std::max(p.longest_slice, s.length());
  }
  return p;
}

// Pre-test on experts 0..4 by a learner who never shows skill 7.
ExpertiseEstimate pretest_missing(const Pool& pool, int missing) {
  std::vector<ExpertiseTrial> trials;
  for (int e = 0; e < 5; ++e) {
    Segmentation student;
    for (const auto& s : pool.skills[static_cast<std::size_t>(e)].segments) {
      if (s.skill != missing) student.segments.push_back(s);
    }
    trials.push_back({e, pool.skills[static_cast<std::size_t>(e)], student, -0.5});
  }
  // Make sure the planted skill is in the pre-test scenarios.
  trials.push_back({5, Segmentation{{{missing, 0, 4}, {2, 4, 9}}}, Segmentation{{{2, 0, 9}}}, -0.5});
  return estimate_expertise(trials, 10, 7);
}

CurriculumInputs inputs_for(const Pool& pool, std::uint64_t seed) {
  CurriculumInputs in;
  in.expert_skills = pool.skills;
  in.expert_time_slices = pool.time_slices;
  in.pretest = pretest_missing(pool, 7);
  in.seed = seed;
  return in;
}

TEST(Curriculum, DefaultBudgetIsThreeCommonSkillsThreeSessionsEach) {
  const Pool pool = make_pool();
  const CurriculumInputs in = inputs_for(pool, 1);
  const Curriculum skills = make_curriculum(StudyCondition::Skills, in, CurriculumConfig::parking());
  ASSERT_EQ(skills.items.size(), 3u);
  EXPECT_EQ(skills.total_steps(), skills.budget_steps);
  EXPECT_EQ(skills.budget_steps, curriculum_budget_steps(in, CurriculumConfig::parking()));

  std::map<int, int> counts;
  for (const auto& seg : pool.skills) {
    for (const auto& s : seg.segments) ++counts[s.skill];
  }
  std::vector<std::pair<int, int>> by_count;  // (-count, skill)
  for (const auto& [m, c] : counts) by_count.push_back({-c, m});
  std::sort(by_count.begin(), by_count.end());
  for (std::size_t i = 0; i < 3; ++i) {
    const PracticeItem& item = skills.items[i];
    EXPECT_EQ(item.kind, PracticeKind::Skill);
    EXPECT_EQ(item.sessions, 3);
    EXPECT_EQ(item.target_skills, (std::vector<int>{by_count[i].second}));
    ASSERT_EQ(item.material.segments.size(), 1u);
    EXPECT_EQ(item.material.segments[0].skill, by_count[i].second);
  }
}

// Tolerance (the documented budget rule): |total - budget| <= half of the longest session a condition
// can offer. Measured on this pool: totals within 9 steps (15%) of budgets of 63-75 steps.
TEST(Curriculum, EveryConditionPractisesRoughlyTheSameNumberOfSteps) {
  const Pool pool = make_pool();
  const CurriculumConfig config = CurriculumConfig::parking();
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const CurriculumInputs in = inputs_for(pool, seed);
    const int budget = curriculum_budget_steps(in, config);
    const int drill_max = config.drills.repetitions * config.drills.ngram_length * pool.longest_segment;
    const std::map<StudyCondition, int> longest_session = {
        {StudyCondition::FullTrajectory, pool.longest_trajectory}, {StudyCondition::TimeHeuristic, pool.longest_slice},
        {StudyCondition::Skills, pool.longest_segment},            {StudyCondition::Drills, drill_max},
        {StudyCondition::IndDrills, drill_max}};
    for (const auto& [condition, longest] : longest_session) {
      const Curriculum c = make_curriculum(condition, in, config);
      EXPECT_EQ(c.budget_steps, budget);
      EXPECT_LE(std::abs(c.total_steps() - budget) * 2, longest)
          << condition_name(condition) << " seed " << seed << ": " << c.total_steps() << " vs " << budget;
      EXPECT_GT(c.items.size(), 0u);
      std::printf("seed %d %-15s budget %3d total %3d items %zu\n", static_cast<int>(seed),
                  std::string(condition_name(condition)).c_str(), budget, c.total_steps(), c.items.size());
    }
    // Adaptive: adaptive_rounds rounds (here without practice evidence) together match the budget.
    std::vector<AdaptiveRound> rounds = {first_adaptive_round(in, config)};
    while (static_cast<int>(rounds.size()) < config.adaptive_rounds) rounds.push_back(next_round(rounds, {}, in, config));
    int total = 0;
    for (const auto& r : rounds) total += r.practice.total_steps();
    EXPECT_LE(std::abs(total - budget) * 2, config.adaptive_rounds * (drill_max + 1)) << total << " vs " << budget;
  }
}

TEST(Curriculum, ExplicitBudgetsAreFilled) {
  const Pool pool = make_pool();
  CurriculumConfig config = CurriculumConfig::writing();
  config.budget_steps = 400;
  const CurriculumInputs in = inputs_for(pool, 4);
  for (StudyCondition c : {StudyCondition::FullTrajectory, StudyCondition::Skills, StudyCondition::Drills,
                           StudyCondition::IndDrills}) {
    const Curriculum cur = make_curriculum(c, in, config);
    const int drill_max = config.drills.repetitions * config.drills.ngram_length * pool.longest_segment;
    EXPECT_NEAR(cur.total_steps(), 400, 0.5 * std::max(drill_max, pool.longest_trajectory)) << condition_name(c);
  }
}

TEST(Curriculum, FullTrajectoriesAreWholeDistinctExpertDemonstrations) {
  const Pool pool = make_pool();
  CurriculumConfig config = CurriculumConfig::parking();
  config.budget_steps = 300;
  const Curriculum c = make_curriculum(StudyCondition::FullTrajectory, inputs_for(pool, 5), config);
  std::set<int> experts;
  for (const auto& item : c.items) {
    EXPECT_EQ(item.kind, PracticeKind::FullTrajectory);
    const int e = item.material.segments.front().expert;
    experts.insert(e);
    const Segmentation& seg = pool.skills[static_cast<std::size_t>(e)];
    EXPECT_EQ(plan_segmentation(item.material), seg);  // the whole trajectory, from step 0 to T
    EXPECT_EQ(item.material.ngram, seg.skills());
  }
  EXPECT_EQ(experts.size(), c.items.size());
}

TEST(Curriculum, IndividualizedDrillsTargetThePretestWeakness) {
  const Pool pool = make_pool();
  const CurriculumInputs in = inputs_for(pool, 6);
  ASSERT_EQ(in.pretest.ranking.front(), 7);
  const Curriculum c = make_curriculum(StudyCondition::IndDrills, in, CurriculumConfig::parking());
  ASSERT_FALSE(c.items.empty());
  EXPECT_EQ(c.items[0].target_skills, (std::vector<int>{7}));
  EXPECT_NE(std::find(c.items[0].material.ngram.begin(), c.items[0].material.ngram.end(), 7), c.items[0].material.ngram.end());
  const std::vector<int> weakest(in.pretest.ranking.begin(), in.pretest.ranking.begin() + 7);
  for (const auto& item : c.items) {
    EXPECT_EQ(item.kind, PracticeKind::Drill);
    EXPECT_NE(std::find(weakest.begin(), weakest.end(), item.material.target_skill), weakest.end());
  }
}

TEST(Curriculum, RandomDrillsAndTimeSlices) {
  const Pool pool = make_pool();
  const CurriculumInputs in = inputs_for(pool, 7);
  for (const auto& item : make_curriculum(StudyCondition::Drills, in, CurriculumConfig::parking()).items) {
    EXPECT_EQ(item.kind, PracticeKind::Drill);
    EXPECT_EQ(item.material.target_skill, -1);
    EXPECT_FALSE(item.target_skills.empty());
  }
  for (const auto& item : make_curriculum(StudyCondition::TimeHeuristic, in, CurriculumConfig::parking()).items) {
    EXPECT_EQ(item.kind, PracticeKind::TimeSlice);
    const DrillSegment& s = item.material.segments.at(0);
    const auto& slices = pool.time_slices[static_cast<std::size_t>(s.expert)].segments;
    EXPECT_NE(std::find(slices.begin(), slices.end(), SkillSegment{s.skill, s.begin, s.end}), slices.end());
  }
}

TEST(Curriculum, DeterministicPerSeed) {
  const Pool pool = make_pool();
  for (StudyCondition c : kAllStudyConditions) {
    const Curriculum a = make_curriculum(c, inputs_for(pool, 11), CurriculumConfig::parking());
    const Curriculum b = make_curriculum(c, inputs_for(pool, 11), CurriculumConfig::parking());
    EXPECT_EQ(a.items, b.items) << condition_name(c);
  }
  const Curriculum a = make_curriculum(StudyCondition::Drills, inputs_for(pool, 11), CurriculumConfig::parking());
  const Curriculum b = make_curriculum(StudyCondition::Drills, inputs_for(pool, 12), CurriculumConfig::parking());
  EXPECT_NE(a.items, b.items);
}

TEST(Curriculum, MissingMaterialIsAnInputError) {
  const Pool pool = make_pool();
  CurriculumInputs in = inputs_for(pool, 1);
  in.expert_time_slices.clear();
  EXPECT_THROW(make_curriculum(StudyCondition::TimeHeuristic, in, CurriculumConfig::parking()), InputError);
  in.pretest = ExpertiseEstimate{};
  EXPECT_THROW(make_curriculum(StudyCondition::IndDrills, in, CurriculumConfig::parking()), InputError);
  EXPECT_THROW(make_curriculum(StudyCondition::Adaptive, in, CurriculumConfig::parking()), InputError);
  EXPECT_THROW(make_curriculum(StudyCondition::Skills, CurriculumInputs{}, CurriculumConfig::parking()), InputError);
  CurriculumConfig bad = CurriculumConfig::parking();
  bad.sessions_per_skill = 0;
  EXPECT_THROW(make_curriculum(StudyCondition::Skills, inputs_for(pool, 1), bad), InputError);
}

}  // namespace
}  // namespace sc
