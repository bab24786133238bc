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

}  // namespace
}  // namespace sc::review
