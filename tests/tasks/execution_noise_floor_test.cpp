#include "teaching/tasks/execution_noise_floor.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
#include "teaching/tasks/writing_planted_weakness.hpp"

namespace sc {
namespace {

TEST(NoiseFloorCalibration, PercentilesInterpolateBetweenOrderStatistics) {
  NoiseFloorCalibration c;
  EXPECT_THROW(c.percentile(1.0), InputError);
  c.scores = {-1.0, -0.5, -0.25, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(c.percentile(0.0), -1.0);
  EXPECT_DOUBLE_EQ(c.percentile(100.0), 0.0);
  EXPECT_DOUBLE_EQ(c.percentile(50.0), -0.25);
  EXPECT_DOUBLE_EQ(c.percentile(12.5), -0.75);  // halfway between the first two of five
  EXPECT_DOUBLE_EQ(c.floor(), c.percentile(kNoiseFloorPercentile));
}

// The writing kit's floor is the one recorded in the shipped model's sidecar (writing_noise_floor.hpp: 200
// learners at seed 0 gave -0.521). 30 of those learners must bracket it between their 0.5th and 3rd
// percentiles; a sidecar whose floor belongs to another model fails this.
TEST(WritingNoiseFloor, TheShippedFloorIsTheShippedModelsCalibration) {
  ASSERT_TRUE(std::filesystem::exists(asset_dir() / "models" / "writing.pt"));
  const auto kit = make_task_kit(TaskKind::writing);
  ASSERT_TRUE(kit->extractor_notice().empty()) << kit->extractor_notice();
  const auto& writing = dynamic_cast<const WritingKit&>(*kit);
  const ClassicDrawerGlyphs glyphs = ClassicDrawerGlyphs::load();
  const std::vector<std::string> words = pretest_words(writing);
  std::vector<std::vector<Json>> learners;
  for (int i = 0; i < 30; ++i) learners.push_back(planted_pretest_trials(glyphs, words, noise_only_learner(0, i)));
  const NoiseFloorCalibration c = calibrate_noise_floor(*kit, learners);
  std::printf("%s", noise_floor_report(c, kit->execution_noise_floor()).c_str());
  ASSERT_TRUE(kit->execution_noise_floor().has_value());
  EXPECT_GE(kit->execution_noise_floor()->segment, c.percentile(0.5));
  EXPECT_LE(kit->execution_noise_floor()->segment, c.percentile(3.0));
  // The repeated floors: 30 learners give 180 skills of two segments and 60 of three or more, too few for the
  // recorded 1 % of 1200 and 400. Those must lie below these learners' 5th percentile and at most 0.1 below
  // their lowest (measured: the 200 learners' lowest median of three or more is 0.097 below these 30's).
  const NoiseFloor f = kit->execution_noise_floor().value();
  ASSERT_TRUE(f.repeated_twice.has_value() && f.repeated_more.has_value());
  EXPECT_GE(*f.repeated_twice, c.skill_twice.front() - 0.1);
  EXPECT_LE(*f.repeated_twice, percentile_of(c.skill_twice, 5.0, "twice"));
  EXPECT_GE(*f.repeated_more, c.skill_more.front() - 0.1);
  EXPECT_LE(*f.repeated_more, percentile_of(c.skill_more, 5.0, "more"));
}

}  // namespace
}  // namespace sc
