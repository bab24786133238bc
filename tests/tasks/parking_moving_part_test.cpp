#include "teaching/tasks/parking_moving_part.hpp"

#include <memory>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "tests/support/action_sign_extractor.hpp"
#include "tests/support/parking_test_drive.hpp"

namespace sc {
namespace {

StepSequence drive(int standing, double idle_pedal = 0.0, int standing_after = 0) {
  return test::parking_test_drive(standing, idle_pedal, standing_after);
}

TEST(ParkingMovingPart, CountsTheStepsBeforeTheCarMoves) {
  EXPECT_EQ(standing_start_steps(drive(0)), 0);  // 0.9 pedal: 0.9 m/s after the first step
  EXPECT_EQ(standing_start_steps(drive(3)), 3);
  // A pedal resting at 0.2 creeps: 0.2, 0.4, then 0.6 m/s, moving from the third step on.
  EXPECT_EQ(standing_start_steps(drive(4, 0.2)), 2);
}

TEST(ParkingMovingPart, CountsTheStepsAfterTheCarStopsForGood) {
  EXPECT_EQ(standing_end_steps(drive(0)), 0);  // the last step brakes from 0.9 m/s to a stop: it moves
  EXPECT_EQ(standing_end_steps(drive(0, 0.0, 5)), 5);
  EXPECT_EQ(standing_start_steps(drive(0, 0.0, 5)), 0);
}

TEST(ParkingMovingPart, NeverTheWholeDriveNorADriveOfAnotherTask) {
  StepSequence still = drive(5);
  still.states.resize(5 * kParkingStateDim);
  still.actions.resize(5 * kParkingActionDim);
  EXPECT_EQ(standing_start_steps(still), 4);
  EXPECT_EQ(standing_end_steps(still), 4);  // both: and yet one step is read (below)
  const auto inner = std::make_shared<test::ActionSignExtractor>(0);
  const Segmentation one = ParkingMovingPartExtractor(inner).extract(still);
  EXPECT_EQ(inner->lengths, std::vector<int>{1});
  EXPECT_EQ(one.segments, (std::vector<SkillSegment>{{1, 0, 5}}));
  StepSequence writing;
  writing.state_dim = 2;
  writing.action_dim = 2;
  writing.states.assign(8, 0.0f);
  writing.actions.assign(8, 0.0f);
  EXPECT_EQ(standing_start_steps(writing), 0);
  EXPECT_EQ(standing_end_steps(writing), 0);
}

TEST(ParkingMovingPart, SegmentsFromTheFirstMovingStepAndGivesTheStandingStartToTheFirstSkill) {
  auto inner = std::make_shared<test::ActionSignExtractor>(0);
  const ParkingMovingPartExtractor extractor(inner);
  const Segmentation s = extractor.extract(drive(3));
  EXPECT_EQ(inner->lengths, std::vector<int>{12});  // the 3 standing steps were not read
  ASSERT_EQ(s.segments.size(), 2u);
  EXPECT_EQ(s.segments[0], (SkillSegment{2, 0, 9}));   // forward (pedal above +0.1)
  EXPECT_EQ(s.segments[1], (SkillSegment{0, 9, 15}));  // backward
  // Read whole, the standing start is a skill of its own ("no pedal") before the manoeuvre's.
  EXPECT_EQ(inner->extract(drive(3)).segments.size(), 3u);
}

TEST(ParkingMovingPart, GivesTheStandingEndToTheLastSkill) {
  auto inner = std::make_shared<test::ActionSignExtractor>(0);
  const Segmentation s = ParkingMovingPartExtractor(inner).extract(drive(2, 0.0, 5));  // 2 + 12 + 5 steps
  EXPECT_EQ(inner->lengths, std::vector<int>{12});                                     // the manoeuvre alone
  ASSERT_EQ(s.segments.size(), 2u);
  EXPECT_EQ(s.segments[0], (SkillSegment{2, 0, 8}));   // forward, from the start
  EXPECT_EQ(s.segments[1], (SkillSegment{0, 8, 19}));  // back to a stop, to the end
  // Read whole, standing at the end is a skill of its own ("no pedal").
  EXPECT_EQ(inner->extract(drive(2, 0.0, 5)).segments.back(), (SkillSegment{1, 14, 19}));
}

TEST(ParkingMovingPart, ADriveThatMovesAtOnceIsReadAsTheWrappedExtractorReadsIt) {
  auto inner = std::make_shared<test::ActionSignExtractor>(0);
  const ParkingMovingPartExtractor extractor(inner);
  EXPECT_EQ(extractor.extract(drive(0)), inner->extract(drive(0)));
  EXPECT_EQ(extractor.name(), "pedal-sign");
  EXPECT_EQ(extractor.num_skills(), 3);
}

TEST(ParkingMovingPart, ExtractAllAgreesWithExtract) {
  const ParkingMovingPartExtractor extractor(std::make_shared<test::ActionSignExtractor>(0));
  const std::vector<StepSequence> drives{drive(0), drive(2), drive(5, 0.05), drive(1, 0.0, 3), drive(0, 0.0, 2)};
  const std::vector<Segmentation> all = extractor.extract_all(drives);
  ASSERT_EQ(all.size(), drives.size());
  for (std::size_t i = 0; i < drives.size(); ++i) EXPECT_EQ(all[i], extractor.extract(drives[i])) << i;
}

TEST(ParkingMovingPart, RefusesToWrapNothing) { EXPECT_THROW(ParkingMovingPartExtractor(nullptr), InputError); }

}  // namespace
}  // namespace sc
