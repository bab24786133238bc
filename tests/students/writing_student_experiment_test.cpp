// The writing synthetic-student pipeline end to end on a small kit (8 pool words, time-heuristic skills,
// tiny pens, one epoch): seconds. Asserts the pipeline's shape and determinism, never a finding
// (docs/students.md has the full runs).
#include "teaching/students/writing_student_experiment.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/students/writing_student_report.hpp"

namespace sc {
namespace {

const WritingKit& small_kit() {
  static const WritingKit kit(std::make_shared<TimeHeuristicExtractor>(kWritingTimeSlices), "",
                              WritingKitOptions{{}, writing::AlphabetKind::Classic, 8, 0, std::nullopt});
  return kit;
}

WritingStudentExperimentConfig tiny_config(std::uint64_t seed) {
  WritingStudentExperimentConfig c = WritingStudentExperimentConfig::quick();
  c.seed = seed;
  return c;
}

TEST(WritingStudentExperiment, StandardConfigurationHasEveryPlantedDeficit) {
  const WritingStudentExperimentConfig c = WritingStudentExperimentConfig::standard();
  ASSERT_EQ(c.students.size(), 7u);
  EXPECT_EQ(c.evaluation_sets, 15);
  EXPECT_EQ(c.num_targets, 3);
  EXPECT_NO_THROW(c.validate());
}

TEST(WritingStudentExperiment, RunsThePipelineWithEqualSizeDataForEveryCondition) {
  const WritingStudentExperimentConfig config = tiny_config(1);
  const WritingStudentExperimentResult r = run_writing_student_experiment(small_kit(), config);
  EXPECT_EQ(r.pool_size, 8);
  EXPECT_EQ(r.diagnosis_words.size(), 2u);
  ASSERT_EQ(r.evaluation_words.size(), 3u);
  ASSERT_EQ(r.students.size(), config.students.size());
  for (const WritingStudentResult& s : r.students) {
    EXPECT_FALSE(s.diagnosis.targets.empty());
    ASSERT_EQ(s.before_reward.size(), 3u);
    ASSERT_EQ(s.conditions.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(s.before_reward[k]));
      EXPECT_LE(s.before_reward[k], 0.0);
      EXPECT_GE(s.before_reward[k], -1.0);
      const int pairs = s.conditions[0].pairs[k];
      EXPECT_GT(pairs, 0);
      for (const WritingConditionResult& c : s.conditions) {
        ASSERT_EQ(c.reward.size(), 3u);
        EXPECT_TRUE(std::isfinite(c.reward[k]));
        EXPECT_EQ(c.pairs[k], pairs);  // equal data size across conditions
        EXPECT_LE(c.letter_pairs[k], pairs);
        EXPECT_TRUE(std::isfinite(c.finetune_loss[k]));
      }
    }
    for (const std::string& w : r.evaluation_words[0])
      for (const ExpertDemo& d : small_kit().expert_pool()) EXPECT_NE(d.scenario.at("word").get<std::string>(), w);
  }
  EXPECT_EQ(r.students[0].training_pairs, r.expert_pairs - r.students[0].letter_pairs);  // missing 'a'
  const std::vector<WritingComparison> tests = compare_writing_conditions(r);
  EXPECT_EQ(tests.size(), 4 * r.students.size());
  const std::string table = writing_experiment_table(r, small_kit());
  EXPECT_NE(table.find("missing 'a'"), std::string::npos);
  EXPECT_EQ(writing_experiment_json(r, small_kit())["students"].size(), r.students.size());
  // Deterministic.
  const WritingStudentExperimentResult again = run_writing_student_experiment(small_kit(), config);
  EXPECT_EQ(again.students[1].of(StudyCondition::IndDrills).reward, r.students[1].of(StudyCondition::IndDrills).reward);
}

TEST(WritingStudentExperiment, RejectsOutOfRangeConfigurations) {
  WritingStudentExperimentConfig c = tiny_config(0);
  c.evaluation_sets = 0;
  EXPECT_THROW(run_writing_student_experiment(small_kit(), c), InputError);
  c = tiny_config(0);
  c.words_per_set = 31;
  EXPECT_THROW(c.validate(), InputError);
  c = tiny_config(0);
  c.finetune_learning_rate = -1.0;
  EXPECT_THROW(c.validate(), InputError);
  c = tiny_config(0);
  c.students.clear();
  EXPECT_THROW(c.validate(), InputError);
}

}  // namespace
}  // namespace sc
