#include "teaching/review/trial_review.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/error.hpp"
#include "engine/parking/parking_replay.hpp"
#include "tests/review/review_fixture.hpp"

namespace sc::review {
namespace {

using records::TrialKind;

const SessionReview& fixture_review() {
  static const SessionReview review = [] {
    const auto& f = test::parking_review_fixture();
    const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
    return SessionReview(test::parking_kit(), load_session_record(store, f.session_id));
  }();
  return review;
}

int first_seq(TrialKind kind) {
  const auto trials = fixture_review().record().trials_of(kind);
  return trials.empty() ? -1 : trials.front()->seq;
}

// Spans must tile [0, T) in order, each with the kit's words.
void expect_tiling(const std::vector<SkillSpan>& spans, int steps) {
  ASSERT_FALSE(spans.empty());
  int at = 0;
  for (const auto& s : spans) {
    EXPECT_EQ(s.begin, at);
    EXPECT_GT(s.end, s.begin);
    EXPECT_FALSE(s.description.empty());
    at = s.end;
  }
  EXPECT_EQ(at, steps);
}

TEST(TrialReview, PretestTrialHasTheExpertAndBothSegmentations) {
  const TrialReview t = fixture_review().trial(first_seq(TrialKind::Pretest));
  EXPECT_EQ(t.task, TaskKind::parking);
  ASSERT_TRUE(t.expert.has_value());
  EXPECT_FALSE(t.ghost.has_value());
  EXPECT_EQ(t.learner_track.points.size(), static_cast<std::size_t>(t.learner_track.steps()) + 1);
  EXPECT_EQ(t.expert_track.points.size(), static_cast<std::size_t>(t.expert_track.steps()) + 1);
  expect_tiling(t.learner_skills, t.learner_track.steps());
  expect_tiling(t.expert_skills, t.expert_track.steps());
  // The reference start: the car at the origin.
  EXPECT_NEAR(t.learner_track.points.front().x, 0.0, 1e-6);
  EXPECT_NEAR(t.expert_track.points.front().y, 0.0, 1e-6);
  EXPECT_NE(t.label.find("pre-test"), std::string::npos);
}

TEST(TrialReview, RewardOverTimeEndsAtTheStoredScore) {
  const TrialReview t = fixture_review().trial(first_seq(TrialKind::Pretest));
  ASSERT_EQ(t.rewards.size(), static_cast<std::size_t>(t.learner_track.steps()));
  ASSERT_TRUE(t.stored.record.score.has_value());
  // Parking's episode score is the last control step's reward (reference-facts).
  EXPECT_NEAR(t.rewards.back(), *t.stored.record.score, 1e-9);
  EXPECT_NEAR(t.reward_times.back(), 0.2 * t.learner_track.steps(), 1e-9);
  for (double r : t.rewards) EXPECT_LE(r, 0.0);
}

TEST(TrialReview, PracticeTrialShowsTheDrillGhostWithItsPlannedSkills) {
  const int seq = first_seq(TrialKind::Practice);
  ASSERT_GT(seq, 0);
  const TrialReview t = fixture_review().trial(seq);
  ASSERT_TRUE(t.ghost.has_value());
  EXPECT_FALSE(t.expert.has_value());
  expect_tiling(t.ghost_skills, t.ghost_track.steps());
  // The learner started where the drill starts.
  EXPECT_NEAR(t.learner_track.points.front().x, t.ghost_track.points.front().x, 1e-3);
  EXPECT_NEAR(t.learner_track.points.front().y, t.ghost_track.points.front().y, 1e-3);
  // The ghost's skills are the stored drill's n-gram.
  const auto* curriculum = fixture_review().record().curriculum(t.stored.record.round);
  ASSERT_NE(curriculum, nullptr);
  const Json stored_skills =
      Json::parse(curriculum->drills.at(static_cast<std::size_t>(*t.stored.record.drill_index)).skills_json);
  ASSERT_EQ(stored_skills.size(), t.ghost_skills.size());
  for (std::size_t i = 0; i < t.ghost_skills.size(); ++i)
    EXPECT_EQ(stored_skills[i].get<int>(), t.ghost_skills[i].skill);
}

TEST(TrialReview, EvaluationTrialGetsARePlannedExpert) {
  const TrialReview t = fixture_review().trial(first_seq(TrialKind::Eval));
  ASSERT_TRUE(t.expert.has_value());
  EXPECT_EQ(t.expert->at("scenario"), Json::parse(t.stored.record.scenario_json));
  // The expert parks, and its track ends where its replay ends.
  const ParkingReplay replay = replay_parking_trial(parse_parking_trial(*t.expert, "expert"));
  EXPECT_GT(replay.success_step, 0);
  EXPECT_NEAR(t.expert_track.points.back().x, replay.steps.back().vehicle.x, 1e-9);
  EXPECT_NEAR(t.expert_track.points.back().y, replay.steps.back().vehicle.y, 1e-9);
}

TEST(TrialReview, UnknownTrialIsAnInputError) { EXPECT_THROW(fixture_review().trial(999), InputError); }

}  // namespace
}  // namespace sc::review
