#include "teaching/review/expertise_rounds.hpp"

#include <gtest/gtest.h>

#include "teaching/expertise/expertise_json.hpp"
#include "tests/review/review_fixture.hpp"

namespace sc::review {
namespace {

TEST(ExpertiseRounds, EchoesTheStoredDiagnosisPerSkill) {
  const auto& f = test::parking_review_fixture();
  const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
  const SessionRecord record = load_session_record(store, f.session_id);
  ASSERT_EQ(record.diagnoses.size(), 1u);
  const ExpertiseRounds rounds = expertise_rounds(test::parking_kit(), record);
  ASSERT_EQ(rounds.rounds, std::vector<int>{1});
  const Json doc = Json::parse(record.diagnoses[0].expertise_json);
  const ExpertiseEstimate stored = expertise_from_json(JsonView(doc, "diagnosis"));
  const Json targets = Json::parse(record.diagnoses[0].targets_json);
  int seen = 0;
  for (int m = 0; m < stored.num_skills(); ++m) seen += stored.occurrences[static_cast<std::size_t>(m)] > 0;
  ASSERT_EQ(static_cast<int>(rounds.skills.size()), seen);
  int targeted = 0;
  for (const auto& s : rounds.skills) {
    ASSERT_EQ(s.expertise.size(), 1u);
    ASSERT_TRUE(s.expertise[0].has_value());
    EXPECT_DOUBLE_EQ(*s.expertise[0], stored.expertise[static_cast<std::size_t>(s.skill)]);
    EXPECT_GE(*s.expertise[0], rounds.lowest);
    EXPECT_FALSE(s.description.empty());
    targeted += s.targeted[0];
  }
  EXPECT_EQ(targeted, static_cast<int>(targets.size()));
  EXPECT_LT(rounds.lowest, 0.0);  // the scripted learner at 0.6 misses skills
}

}  // namespace
}  // namespace sc::review
