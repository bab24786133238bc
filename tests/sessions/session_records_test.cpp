// The records a session writes: the layout docs/database.md describes.
#include "teaching/sessions/session_records.hpp"

#include <gtest/gtest.h>

namespace sc {
namespace {

TEST(SessionRecords, SessionRowCarriesTheSettings) {
  SessionSettings settings;
  settings.learner = "Ada";
  settings.condition = StudyCondition::IndDrills;
  settings.seed = 7;
  settings.goal_region = GoalRegion::StudyCorner;
  const records::NewSession row = session_record(settings, "parking", "2024-05-01T12:00:00.000Z");
  EXPECT_EQ(row.learner, "Ada");
  EXPECT_EQ(row.task, "parking");
  EXPECT_EQ(row.condition, "ind-drills");
  EXPECT_EQ(row.seed, 7u);
  EXPECT_EQ(Json::parse(row.settings_json).at("goal_region"), "study-corner");
}

TEST(SessionRecords, CurriculumHasOneDrillRowPerItem) {
  Curriculum c;
  c.condition = StudyCondition::IndDrills;
  PracticeItem item;
  item.target_skills = {3};
  item.material.segments = {{0, 3, 2, 9}};
  item.sessions = 2;
  c.items = {item, item};
  const records::CurriculumRecord row = curriculum_record(5, 2, c.condition, c, "t");
  EXPECT_EQ(row.session_id, 5);
  EXPECT_EQ(row.round, 2);
  ASSERT_EQ(row.drills.size(), 2u);
  EXPECT_EQ(row.drills[1].index, 1);
  const Json drill = Json::parse(row.drills[0].content_json);
  EXPECT_EQ(drill.at("sessions"), 2);
  EXPECT_EQ(drill.at("steps"), 7);
}

TEST(SessionRecords, TrialRowKeepsTheDocumentAndItsScenario) {
  const Json trial{{"task", "writing"}, {"scenario", {{"word", "ba"}}}, {"points", Json::array()}};
  const records::TrialRecord row =
      trial_record({9, records::TrialKind::Practice, 1, 4}, "writing", "mouse", trial, -0.25);
  EXPECT_EQ(Json::parse(row.scenario_json), trial.at("scenario"));
  EXPECT_EQ(Json::parse(row.trajectory_json), trial);
  EXPECT_EQ(row.drill_index, 4);
  EXPECT_EQ(row.score, -0.25);
  EXPECT_EQ(
      trial_record({9, records::TrialKind::Demo, 1, 4}, "writing", "mouse", Json::object(), std::nullopt).scenario_json,
      "{}");
}

}  // namespace
}  // namespace sc
