#include "teaching/tasks/skill_training_data.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

TEST(SkillTrainingData, WritingWordsCarryTheirCharacterBoundaries) {
  const SkillDataSet data = generate_writing_demos(5, 0);
  ASSERT_EQ(data.demos.size(), 5u);
  for (const SkillDemo& d : data.demos) {
    EXPECT_EQ(d.label.size(), 8u);  // the reference's generator: 8-symbol words
    ASSERT_EQ(d.true_boundaries.size(), 7u) << d.label;
    EXPECT_GT(d.true_boundaries.front(), 0);
    EXPECT_LT(d.true_boundaries.back(), d.steps.length());
    EXPECT_TRUE(std::is_sorted(d.true_boundaries.begin(), d.true_boundaries.end()));
    EXPECT_EQ(d.steps.action_dim, 2);
  }
  EXPECT_EQ(generate_writing_demos(5, 0).demos[3].label, data.demos[3].label);  // deterministic
}

TEST(SkillTrainingData, AugmentedCopiesKeepTheCleanWordsStepsAndWarmBoundaries) {
  const SkillDataSet data = generate_augmented_writing_demos(6, 1, 2);
  ASSERT_EQ(data.demos.size(), 12u);
  ASSERT_EQ(data.warm_boundaries.size(), 12u);
  for (std::size_t i = 0; i < 12; i += 2) {
    const SkillDemo& clean = data.demos[i];
    const SkillDemo& copy = data.demos[i + 1];
    EXPECT_EQ(copy.steps.length(), clean.steps.length()) << clean.label;  // the perturbation keeps step indices
    EXPECT_NE(copy.steps.actions, clean.steps.actions) << clean.label;
    EXPECT_EQ(copy.true_boundaries, clean.true_boundaries);
    EXPECT_EQ(data.warm_boundaries[i + 1], data.warm_boundaries[i]);  // inherited, not found anew
  }
  // Split: the training lists of warm boundaries follow the training demos.
  const DataSplit split = split_demos(data, 0.25, 0);
  EXPECT_EQ(split.train_warm_boundaries.size(), split.train.size());
}

TEST(SkillTrainingData, MouseSampledCopiesMoveTheirInheritedBoundariesWithTheReadings) {
  const SkillDataSet data = generate_augmented_writing_demos(6, 1, 2, {AugmentDrawers::PaperOnly, true});
  ASSERT_EQ(data.demos.size(), 12u);
  int same_length = 0;
  for (std::size_t i = 0; i < 12; i += 2) {
    const SkillDemo& clean = data.demos[i];
    const SkillDemo& copy = data.demos[i + 1];
    same_length += copy.steps.length() == clean.steps.length();
    ASSERT_EQ(copy.true_boundaries.size(), clean.true_boundaries.size()) << clean.label;
    ASSERT_EQ(data.warm_boundaries[i + 1].size(), data.warm_boundaries[i].size()) << clean.label;
    // Each boundary sits at the same share of the word (within a few percent: the pace varies along it).
    for (std::size_t k = 0; k < clean.true_boundaries.size(); ++k) {
      const double clean_share = static_cast<double>(clean.true_boundaries[k]) / clean.steps.length();
      const double copy_share = static_cast<double>(copy.true_boundaries[k]) / copy.steps.length();
      EXPECT_NEAR(copy_share, clean_share, 0.15) << clean.label << " boundary " << k;
    }
    const auto& warm = data.warm_boundaries[i + 1];
    EXPECT_TRUE(std::is_sorted(warm.begin(), warm.end()));
    if (!warm.empty()) {
      EXPECT_LT(warm.back(), copy.steps.length());
    }
  }
  EXPECT_LT(same_length, 6);  // the readings are not the pen steps
  EXPECT_NE(data.description.find("mouse-sampled"), std::string::npos) << data.description;
}

TEST(SkillTrainingData, OtherHandCopiesCarryTheCleanWordsWarmBoundariesAndUnitsToOtherLetters) {
  const SkillDataSet data = generate_augmented_writing_demos(8, 0, 2, {AugmentDrawers::PaperOnly, false, 1});
  ASSERT_EQ(data.demos.size(), 16u);
  ASSERT_EQ(data.warm_units.size(), 16u);
  int other_length = 0, near = 0, carried = 0;
  for (std::size_t i = 0; i < 16; i += 2) {
    const SkillDemo& clean = data.demos[i];
    const SkillDemo& copy = data.demos[i + 1];
    EXPECT_NE(copy.label.find("other hand"), std::string::npos) << copy.label;
    other_length += copy.steps.length() != clean.steps.length();  // other drawers' letters, other step counts
    const auto& warm = data.warm_boundaries[i + 1];
    EXPECT_TRUE(std::is_sorted(warm.begin(), warm.end()));
    ASSERT_EQ(data.warm_units[i + 1].size(), warm.size() + 1) << clean.label;
    if (warm.size() == data.warm_boundaries[i].size()) {
      EXPECT_EQ(data.warm_units[i + 1], data.warm_units[i]) << clean.label;  // nothing dropped: the same units
    }
    // The warm start's boundaries of a clean word are its letter starts (repeats), so the carried ones should
    // land near the copy's own letter starts - which training never reads.
    const double tolerance = 0.05 * copy.steps.length();
    for (int b : warm) {
      ++carried;
      for (int t : copy.true_boundaries) {
        if (std::abs(b - t) <= tolerance) {
          ++near;
          break;
        }
      }
    }
  }
  EXPECT_GE(other_length, 6);
  EXPECT_GE(near, 0.8 * carried);
  EXPECT_NE(data.description.find("drawers 1-10 aligned"), std::string::npos) << data.description;
}

TEST(SkillTrainingData, ParkingDemosAreParkedExpertPlans) {
  const SkillDataSet data = generate_parking_demos(3, 11);
  ASSERT_FALSE(data.demos.empty());
  for (const SkillDemo& d : data.demos) {
    EXPECT_EQ(d.steps.state_dim, 12);
    EXPECT_GT(d.steps.length(), 5);
  }
  EXPECT_NE(data.description.find("out of 3 random classic scenarios"), std::string::npos) << data.description;
}

TEST(SkillTrainingData, SplitHoldsOutATenthChosenByTheSeed) {
  const SkillDataSet data = generate_writing_demos(20, 1);
  const DataSplit a = split_demos(data, 0.1, 4), b = split_demos(data, 0.1, 4), c = split_demos(data, 0.1, 5);
  EXPECT_EQ(a.valid.size(), 2u);
  EXPECT_EQ(a.train.size(), 18u);
  EXPECT_EQ(a.valid[0].actions, b.valid[0].actions);
  std::set<std::size_t> lengths_a, lengths_c;
  for (const auto& s : a.valid) lengths_a.insert(s.actions.size());
  for (const auto& s : c.valid) lengths_c.insert(s.actions.size());
  EXPECT_NE(lengths_a, lengths_c);  // another seed holds out other words
  EXPECT_EQ(split_demos(SkillDataSet{"writing", "", {data.demos[0], data.demos[1]}, {}, {}}, 0.1, 0).valid.size(), 1u);
}

TEST(SkillTrainingData, FolderWithoutTrialsOrWithAForeignTrialIsRefused) {
  const auto dir = test::scratch_path("skill_training_data", "folder");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  EXPECT_THROW(read_task_demos(TaskKind::writing, dir), InputError);
  write_json_file(dir / "a.json", Json{{"task", "parking"}});
  try {
    read_task_demos(TaskKind::writing, dir);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sc
