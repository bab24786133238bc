#include "teaching/curricula/study_condition.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc {
namespace {

TEST(StudyCondition, NamesAndKeysRoundTrip) {
  for (StudyCondition c : kAllStudyConditions) {
    EXPECT_EQ(parse_condition(condition_key(c)), c);
    EXPECT_EQ(parse_condition(condition_name(c)), c);
  }
  EXPECT_EQ(condition_name(StudyCondition::IndDrills), "Ind. Drills");
  EXPECT_EQ(parse_condition("FULL TRAJECTORY"), StudyCondition::FullTrajectory);
}

TEST(StudyCondition, UnknownNamesListTheValidKeys) {
  try {
    parse_condition("cramming");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ind-drills"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sc
