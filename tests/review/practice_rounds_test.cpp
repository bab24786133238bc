#include "teaching/review/practice_rounds.hpp"

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "teaching/curricula/curriculum_json.hpp"
#include "tests/review/review_fixture.hpp"

namespace sc::review {
namespace {

TEST(PracticeRounds, StatePlannedAndPlayedPracticeAgainstTheBudget) {
  const auto& f = test::parking_review_fixture();
  const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
  const SessionRecord record = load_session_record(store, f.session_id);
  const std::vector<PracticeRound> rounds = practice_rounds(record);
  ASSERT_EQ(rounds.size(), record.curricula.size());
  ASSERT_FALSE(rounds.empty());
  for (std::size_t r = 0; r < rounds.size(); ++r) {
    const Json doc = Json::parse(record.curricula[r].items_json);
    const Curriculum stored = curriculum_from_json(JsonView(doc, "curriculum"));
    EXPECT_EQ(rounds[r].round, record.curricula[r].round);
    EXPECT_EQ(rounds[r].planned_trials, stored.trials());
    EXPECT_EQ(rounds[r].steps, stored.total_steps());
    EXPECT_EQ(rounds[r].budget_steps, stored.budget_steps);
    EXPECT_GT(rounds[r].budget_steps, 0);
    EXPECT_EQ(rounds[r].played_trials,
              static_cast<int>(record.trials_of(records::TrialKind::Practice, rounds[r].round).size()));
  }
  PracticeRound one{1, "Skills", 12, 150, 152, 11};
  EXPECT_EQ(practice_round_text(one),
            "Round 1, Skills: 12 trials planned, 11 played; 150 time-steps of a 152-step budget (-1.3 %)");
}

TEST(PracticeRounds, UnreadableCurriculumNamesTheSession) {
  SessionRecord record;
  record.session.id = 9;
  record.curricula.push_back({9, 1, "skills", "{\"items\": 3}", {}, ""});
  try {
    practice_rounds(record);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("session 9 curriculum of round 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sc::review
