#include "teaching/curricula/curriculum.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <string>

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

TEST(Curriculum, SkillsPractiseTheThreeMostCommonSkillsThreeSessionsEach) {
  const Pool pool = make_pool();
  const CurriculumInputs in = inputs_for(pool, 1);
  const Curriculum skills = make_curriculum(StudyCondition::Skills, in, CurriculumConfig::parking());
  ASSERT_GE(skills.items.size(), 3u);
  EXPECT_EQ(skills.budget_steps, curriculum_budget_steps(in, CurriculumConfig::parking()));

  std::map<int, int> counts;
  for (const auto& seg : pool.skills) {
    for (const auto& s : seg.segments) ++counts[s.skill];
  }
  std::vector<std::pair<int, int>> by_count;  // (-count, skill)
  for (const auto& [m, c] : counts) by_count.push_back({-c, m});
  std::sort(by_count.begin(), by_count.end());
  for (std::size_t i = 0; i < skills.items.size(); ++i) {
    const PracticeItem& item = skills.items[i];
    const int skill = by_count[i % 3].second;  // further passes repeat the three skills in order
    EXPECT_EQ(item.kind, PracticeKind::Skill);
    if (i < 3) {
      EXPECT_EQ(item.sessions, 3);
    }
    EXPECT_EQ(item.target_skills, (std::vector<int>{skill}));
    ASSERT_EQ(item.material.segments.size(), 1u);
    EXPECT_EQ(item.material.segments[0].skill, skill);
  }
}

TEST(Curriculum, IndDrillsRoundIsTwoUniqueDrillsForEachOfTheThreeWeakestSkills) {
  const Pool pool = make_pool();
  const CurriculumInputs in = inputs_for(pool, 2);
  const Curriculum c = make_curriculum(StudyCondition::IndDrills, in, CurriculumConfig::parking());
  ASSERT_EQ(c.items.size(), 6u);
  EXPECT_EQ(c.trials(), 6);
  EXPECT_EQ(c.budget_steps, c.total_steps());  // the reference arm
  std::set<std::vector<int>> ngrams;
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(c.items[i].target_skills, (std::vector<int>{in.pretest.ranking[i / 2]})) << i;
    EXPECT_EQ(c.items[i].sessions, 1);
    ngrams.insert(c.items[i].material.ngram);
  }
  EXPECT_EQ(ngrams.size(), 6u);  // unique drills

  CurriculumConfig config = CurriculumConfig::parking();
  config.weak_skills = 2;
  config.drills_per_weak_skill = 1;
  EXPECT_EQ(make_curriculum(StudyCondition::IndDrills, in, config).trials(), 2);
}

// The default budget: Ind. Drills' round is the reference; every other arm within ±4.5 % of it, so any
// two arms differ by less than 10 %.
TEST(Curriculum, EveryArmPractisesTheReferenceBudgetWithinTheTolerance) {
  const Pool pool = make_pool();
  const CurriculumConfig config = CurriculumConfig::parking();
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const CurriculumInputs in = inputs_for(pool, seed);
    const int budget = curriculum_budget_steps(in, config);
    const Curriculum reference = make_curriculum(StudyCondition::IndDrills, in, config);
    EXPECT_EQ(reference.total_steps(), budget);
    int lowest = budget;
    int highest = budget;
    for (StudyCondition condition : kAllStudyConditions) {
      const Curriculum c = make_curriculum(condition, in, config);
      EXPECT_EQ(c.budget_steps, budget) << condition_name(condition);
      EXPECT_LE(std::abs(c.total_steps() - budget), config.budget_tolerance * budget)
          << condition_name(condition) << " seed " << seed << ": " << c.total_steps() << " vs " << budget;
      lowest = std::min(lowest, c.total_steps());
      highest = std::max(highest, c.total_steps());
      std::printf("seed %d %-15s budget %3d total %3d trials %d\n", static_cast<int>(seed),
                  std::string(condition_name(condition)).c_str(), budget, c.total_steps(), c.trials());
    }
    EXPECT_LT(highest, 1.10 * lowest);
    // Adaptive's first round is Ind. Drills' round.
    EXPECT_EQ(make_curriculum(StudyCondition::Adaptive, in, config).items, reference.items);
  }
}

// Whole trajectories are coarse material: when every trajectory left is longer than the gap to the window,
// the fill has to give one back and try another length (the study corner's 15-25-step drives did this).
TEST(Curriculum, LongTrajectoriesStillLandWithinTheTolerance) {
  Pool pool = make_pool();
  Rng rng(77);
  for (Segmentation& seg : pool.skills) {
    const int first = 8 + static_cast<int>(rng.below(5)), second = 8 + static_cast<int>(rng.below(6));
    const int a = seg.segments.front().skill, b = seg.segments.back().skill;
    seg.segments = {{a, 0, first}, {b, first, first + second}};
  }
  const CurriculumConfig config = CurriculumConfig::parking();
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const CurriculumInputs in = inputs_for(pool, seed);
    const int budget = curriculum_budget_steps(in, config);
    const Curriculum c = make_curriculum(StudyCondition::FullTrajectory, in, config);
    EXPECT_LE(std::abs(c.total_steps() - budget), config.budget_tolerance * budget)
        << "seed " << seed << ": " << c.total_steps() << " vs " << budget;
  }
}

TEST(Curriculum, ExplicitBudgetsAreFilled) {
  const Pool pool = make_pool();
  CurriculumConfig config = CurriculumConfig::writing();
  config.budget_steps = 400;
  const CurriculumInputs in = inputs_for(pool, 4);
  for (StudyCondition c :
       {StudyCondition::FullTrajectory, StudyCondition::Skills, StudyCondition::Drills, StudyCondition::IndDrills}) {
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

TEST(Curriculum, SkillsTooBriefToPractiseAreNeitherTargetsNorPractisedAlone) {
  Pool pool = make_pool();
  // Skill 7 (the planted weakness) becomes a 2-step filler everywhere.
  for (auto& seg : pool.skills) {
    int t = 0;
    for (auto& s : seg.segments) {
      const int len = s.skill == 7 ? 2 : s.length();
      s = {s.skill, t, t + len};
      t += len;
    }
  }
  CurriculumConfig config = CurriculumConfig::parking();
  config.min_skill_steps = 3;
  CurriculumInputs in = inputs_for(pool, 6);
  in.pretest = pretest_missing(pool, 7);
  ASSERT_EQ(in.pretest.ranking.front(), 7);
  bool inside_a_drill = false;
  for (StudyCondition condition : kAllStudyConditions) {
    for (const auto& item : make_curriculum(condition, in, config).items) {
      if (item.kind == PracticeKind::Skill || item.material.target_skill >= 0) {
        EXPECT_NE(item.target_skills, (std::vector<int>{7})) << condition_name(condition);
      }
      for (const auto& s : item.material.segments) inside_a_drill = inside_a_drill || s.skill == 7;
    }
  }
  EXPECT_TRUE(inside_a_drill);  // it still appears between other skills
}

TEST(Curriculum, IndividualizedDrillsTargetThePretestWeakness) {
  const Pool pool = make_pool();
  const CurriculumInputs in = inputs_for(pool, 6);
  ASSERT_EQ(in.pretest.ranking.front(), 7);
  const Curriculum c = make_curriculum(StudyCondition::IndDrills, in, CurriculumConfig::parking());
  ASSERT_FALSE(c.items.empty());
  EXPECT_EQ(c.items[0].target_skills, (std::vector<int>{7}));
  EXPECT_NE(std::find(c.items[0].material.ngram.begin(), c.items[0].material.ngram.end(), 7),
            c.items[0].material.ngram.end());
  for (const auto& item : c.items) EXPECT_EQ(item.kind, PracticeKind::Drill);
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

TEST(Curriculum, PlayedDrillsAndSkillItemsCountForTheirSkillsTimeSlicesForNone) {
  Curriculum c;
  c.items.push_back({PracticeKind::Drill, {4}, {}, 1});
  c.items.push_back({PracticeKind::Skill, {2}, {}, 3});
  c.items.push_back({PracticeKind::TimeSlice, {1}, {}, 1});
  c.items.push_back({PracticeKind::FullTrajectory, {2, 4}, {}, 1});
  // Item 0 played twice (one more on that skill), item 1 once, the slice and the trajectory once each.
  EXPECT_EQ(practice_trials_per_skill(c, {0, 0, 1, 2, 3}), (std::map<int, int>{{2, 1}, {4, 2}}));
  EXPECT_TRUE(practice_trials_per_skill(c, {}).empty());
  EXPECT_THROW(practice_trials_per_skill(c, {4}), InputError);
}

TEST(Curriculum, TimeHeuristicPractisesThreeDifferentIntervalsDrawnPerLearner) {
  Pool pool = make_pool();
  for (std::size_t e = 0; e < pool.skills.size(); ++e) {  // K = 8 equal slices, as for writing
    const int t = pool.skills[e].segments.back().end;
    Segmentation slices;
    for (int k = 0; k < 8; ++k) slices.segments.push_back({k, k * t / 8, (k + 1) * t / 8});
    pool.time_slices[e] = slices;
  }
  std::set<std::set<int>> drawn;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Curriculum c =
        make_curriculum(StudyCondition::TimeHeuristic, inputs_for(pool, seed), CurriculumConfig::parking());
    std::set<int> intervals;
    for (const auto& item : c.items) intervals.insert(item.target_skills.at(0));
    EXPECT_EQ(intervals.size(), 3u) << "seed " << seed;
    drawn.insert(intervals);
  }
  EXPECT_GT(drawn.size(), 1u);  // not always the same three
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
