#include "teaching/review/diagnosis_explained.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/review/review_fixture.hpp"

namespace sc::review {
namespace {

TEST(DiagnosisExplained, RecomputesTheStoredDiagnosisAndListsTheMisses) {
  const auto& f = test::parking_review_fixture();
  const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
  const SessionReview review(test::parking_kit(), load_session_record(store, f.session_id));
  const DiagnosisExplanation e = explain_diagnosis(review);
  EXPECT_TRUE(e.matches_stored);
  EXPECT_EQ(e.pretest_trials, 3);
  ASSERT_FALSE(e.stored_targets.empty());
  EXPECT_EQ(e.stored_targets, e.recomputed_targets);
  ASSERT_EQ(e.skills.size(), e.stored_targets.size());
  std::vector<int> pretest;
  for (const auto* t : review.record().trials_of(records::TrialKind::Pretest)) pretest.push_back(t->seq);
  for (const auto& s : e.skills) {
    EXPECT_FALSE(s.description.empty());
    EXPECT_GT(s.occurrences, 0);
    double sum = 0.0;
    for (const auto& m : s.missed) {
      EXPECT_NE(std::find(pretest.begin(), pretest.end(), m.seq), pretest.end());
      EXPECT_GE(m.position, 1);
      EXPECT_NEAR(m.delta, -m.reward / m.position, 1e-12);
      sum += m.delta;
    }
    EXPECT_NEAR(s.expertise, -sum, 1e-9);  // E_m = -sum of its deltas
  }
  // The weakest target was missed at least once (a target without a miss would be a tie at 0).
  EXPECT_FALSE(e.skills.front().missed.empty());
}

TEST(DiagnosisExplained, EachChargedTargetSaysWhereItsLargestPenaltyHappened) {
  const auto& f = test::parking_review_fixture();
  const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
  const SessionReview review(test::parking_kit(), load_session_record(store, f.session_id));
  const DiagnosisExplanation e = explain_diagnosis(review);
  int placed = 0;
  for (const auto& s : e.skills) {
    ASSERT_EQ(s.place.has_value(), !s.missed.empty()) << "skill " << s.skill;
    if (!s.place) continue;
    ++placed;
    const auto largest = std::max_element(s.missed.begin(), s.missed.end(),
                                          [](const auto& a, const auto& b) { return a.delta < b.delta; });
    EXPECT_EQ(s.place->seq, largest->seq);
    EXPECT_EQ(s.place->reason == TargetReason::LargeError, largest->execution);
    EXPECT_GE(s.place->learner_begin, 0);
    EXPECT_LE(s.place->learner_begin, s.place->learner_end);
    EXPECT_LE(s.place->learner_end, s.place->learner_steps);
    EXPECT_EQ(s.place->learner_trial.at("task"), "parking");
    EXPECT_EQ(s.place->expert_trial.at("scenario"), s.place->learner_trial.at("scenario"));
  }
  EXPECT_GT(placed, 0);
}

}  // namespace
}  // namespace sc::review
