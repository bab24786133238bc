#include "teaching/review/before_after.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "engine/core/error.hpp"
#include "tests/review/review_fixture.hpp"

namespace sc::review {
namespace {

TEST(BeforeAfter, ParkingFamiliesFollowTheGoalsSide) {
  const Json lower_left = {{"heading0", 0.0}, {"goal", {{"spot", 3}}}};
  const Json upper_right = {{"heading0", 0.0}, {"goal", {{"spot", 29}}}, {"reverse_in", true}};
  EXPECT_EQ(scenario_family(TaskKind::parking, lower_left, "s").key, "parking-lower-left");
  const ScenarioFamily f = scenario_family(TaskKind::parking, upper_right, "s");
  EXPECT_EQ(f.key, "parking-upper-right-backed-in");
  EXPECT_EQ(f.title, "goal in the upper row, right of the start, backed in");
}

TEST(BeforeAfter, EveryTestTrialIsInExactlyOneGroup) {
  const auto& f = test::parking_review_fixture();
  const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
  const SessionRecord record = load_session_record(store, f.session_id);
  const auto groups = before_after_groups(record);
  ASSERT_FALSE(groups.empty());
  std::vector<int> pre, eval;
  for (const auto& g : groups) {
    EXPECT_FALSE(g.title.empty());
    pre.insert(pre.end(), g.pretest_seqs.begin(), g.pretest_seqs.end());
    eval.insert(eval.end(), g.eval_seqs.begin(), g.eval_seqs.end());
  }
  std::sort(pre.begin(), pre.end());
  std::sort(eval.begin(), eval.end());
  std::vector<int> want_pre, want_eval;
  for (const auto* t : record.trials_of(records::TrialKind::Pretest)) want_pre.push_back(t->seq);
  for (const auto* t : record.trials_of(records::TrialKind::Eval)) want_eval.push_back(t->seq);
  EXPECT_EQ(pre, want_pre);
  EXPECT_EQ(eval, want_eval);
  EXPECT_EQ(want_pre.size(), 3u);
  EXPECT_EQ(want_eval.size(), 4u);  // two rounds of two
}

}  // namespace
}  // namespace sc::review
