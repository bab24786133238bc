#include "teaching/learners/parking/augmented_parking_demos.hpp"

#include <set>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/learners/parking/realistic_driver.hpp"
#include "teaching/tasks/skill_training_data.hpp"

namespace sc {
namespace {

TEST(AugmentedParkingDemos, EachCleanPlanIsFollowedByItsCopies) {
  const SkillDataSet clean = generate_parking_demos(2, 4);
  const SkillDataSet data = generate_augmented_parking_demos(2, 2, 4);
  ASSERT_EQ(data.demos.size(), 3 * clean.demos.size());
  EXPECT_EQ(data.task, "parking");
  EXPECT_TRUE(data.warm_boundaries.empty());  // parking has no warm start: nothing is inherited
  for (std::size_t i = 0; i < clean.demos.size(); ++i) {
    const SkillDemo& plan = data.demos[3 * i];
    EXPECT_EQ(plan.label, clean.demos[i].label);
    EXPECT_EQ(plan.steps.actions, clean.demos[i].steps.actions);  // the clean plan, unchanged
    for (int c = 1; c <= 2; ++c) {
      const SkillDemo& copy = data.demos[3 * i + static_cast<std::size_t>(c)];
      EXPECT_EQ(copy.label.rfind(plan.label + " (", 0), 0u) << copy.label;
      EXPECT_NE(copy.label.find("copy " + std::to_string(c) + ")"), std::string::npos) << copy.label;
      EXPECT_EQ(copy.steps.state_dim, plan.steps.state_dim);
      EXPECT_GT(copy.steps.length(), 0);
      EXPECT_NE(copy.steps.actions, plan.steps.actions);  // noise and delay change every drive
      EXPECT_TRUE(copy.true_boundaries.empty());
    }
  }
}

TEST(AugmentedParkingDemos, SameSeedSameDataAndDevicesVary) {
  const SkillDataSet a = generate_augmented_parking_demos(2, 3, 9), b = generate_augmented_parking_demos(2, 3, 9);
  ASSERT_EQ(a.demos.size(), b.demos.size());
  std::set<std::string> devices;
  for (std::size_t i = 0; i < a.demos.size(); ++i) {
    EXPECT_EQ(a.demos[i].label, b.demos[i].label);
    EXPECT_EQ(a.demos[i].steps.actions, b.demos[i].steps.actions);
    EXPECT_EQ(a.demos[i].steps.states, b.demos[i].steps.states);
    const std::string& label = a.demos[i].label;
    if (label.find("copy") != std::string::npos) devices.insert(label.substr(label.find('(') + 1, 4));
  }
  EXPECT_GE(devices.size(), 2u) << "the device is drawn per copy";
}

TEST(AugmentedParkingDemos, NoCopiesIsTheCleanDataAndBadCountsAreRefused) {
  EXPECT_EQ(generate_augmented_parking_demos(1, 0, 1).demos.size(), generate_parking_demos(1, 1).demos.size());
  EXPECT_THROW(generate_augmented_parking_demos(0, 1, 1), InputError);
  EXPECT_THROW(generate_augmented_parking_demos(1, -1, 1), InputError);
}

TEST(AugmentedParkingDemos, AKeyedCopyIsTheCleanMotionWithKeyboardKeysForActions) {
  const SkillDataSet plain = generate_augmented_parking_demos(2, 1, 4);
  const SkillDataSet data = generate_augmented_parking_demos(2, 1, 4, true);
  ASSERT_EQ(data.demos.size(), plain.demos.size() / 2 * 3);
  for (std::size_t i = 0; i < data.demos.size(); i += 3) {
    const SkillDemo& plan = data.demos[i];
    EXPECT_EQ(data.demos[i + 1].steps.actions, plain.demos[i / 3 * 2 + 1].steps.actions);  // the copies as before
    const SkillDemo& keyed = data.demos[i + 2];
    EXPECT_EQ(keyed.label, plan.label + " (keyboard keys)");
    EXPECT_EQ(keyed.steps.states, plan.steps.states);  // the same motion
    ASSERT_EQ(keyed.steps.actions.size(), plan.steps.actions.size());
    for (std::size_t k = 0; k + 1 < keyed.steps.actions.size(); k += 2) {
      const ParkingAction keys = keyboard_keys({plan.steps.actions[k], plan.steps.actions[k + 1]});
      EXPECT_FLOAT_EQ(keyed.steps.actions[k], static_cast<float>(keys[0]));
      EXPECT_FLOAT_EQ(keyed.steps.actions[k + 1], static_cast<float>(keys[1]));
    }
    EXPECT_NE(keyed.steps.actions, plan.steps.actions);
  }
}

}  // namespace
}  // namespace sc
