#include "teaching/tasks/parking_drive_reading.hpp"

#include <memory>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "tests/support/action_sign_extractor.hpp"
#include "tests/support/parking_test_drive.hpp"

namespace sc {
namespace {

using test::parking_test_drive;

TEST(ParkingDriveReading, ThePieceLengthIsTheLongestMovingPart) {
  // 12 and 24 moving steps; standing still at either end does not count.
  EXPECT_EQ(longest_moving_drive({parking_test_drive(3, 0.0, 5), parking_test_drive(0, 0.0, 0, 2)}), 24);
  EXPECT_EQ(longest_moving_drive({}), 1);
}

TEST(ParkingDriveReading, ReadsTheMovingPartOfALongDriveInPieces) {
  auto model = std::make_shared<test::ActionSignExtractor>(0);
  const auto reader = parking_drive_reader(model, 12);
  // 2 standing steps, four 12-step manoeuvres, 3 standing steps: 48 moving steps in 4 pieces of 12.
  const Segmentation s = reader->extract(parking_test_drive(2, 0.0, 3, 4));
  EXPECT_EQ(model->lengths, (std::vector<int>{12, 12, 12, 12}));
  ASSERT_FALSE(s.segments.empty());
  EXPECT_EQ(s.segments.front().begin, 0);
  EXPECT_EQ(s.segments.back().end, 53);
  EXPECT_EQ(reader->name(), "pedal-sign");
}

TEST(ParkingDriveReading, ResearchSwitchesReadAsBefore) {
  auto model = std::make_shared<test::ActionSignExtractor>(0);
  parking_drive_reader(model, 12, {.one_piece = true})->extract(parking_test_drive(2, 0.0, 3, 4));
  EXPECT_EQ(model->lengths, (std::vector<int>{48}));  // the moving part, in one piece
  model->lengths.clear();
  parking_drive_reader(model, 12, {.whole_drive = true})->extract(parking_test_drive(2, 0.0, 3, 4));
  EXPECT_EQ(model->lengths, (std::vector<int>{53}));  // all of it, in one piece
}

TEST(ParkingDriveReading, TheTimeHeuristicSlicesTheWholeMovingPart) {
  const auto heuristic = std::make_shared<TimeHeuristicExtractor>(3);
  const Segmentation s = parking_drive_reader(heuristic, 12)->extract(parking_test_drive(0, 0.0, 0, 4));
  EXPECT_EQ(s, heuristic->extract(parking_test_drive(0, 0.0, 0, 4)));
}

TEST(ParkingDriveReading, RefusesNoModel) { EXPECT_THROW(parking_drive_reader(nullptr, 12), InputError); }

}  // namespace
}  // namespace sc
