#include "teaching/review/expertise_rounds.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "teaching/expertise/expertise_json.hpp"
#include "tests/review/review_fixture.hpp"

namespace sc::review {
namespace {

TEST(ExpertiseRounds, EchoesTheStoredDiagnosisOfEveryRound) {
  const auto& f = test::parking_review_fixture();
  const records::LearnerStore store(f.data_dir, records::StoreOptions{.read_only = true});
  const SessionRecord record = load_session_record(store, f.session_id);
  ASSERT_EQ(record.diagnoses.size(), 2u);
  const ExpertiseRounds rounds = expertise_rounds(test::parking_kit(), record);
  ASSERT_EQ(rounds.rounds, (std::vector<int>{1, 2}));
  std::vector<int> seen(static_cast<std::size_t>(test::parking_kit().extractor().num_skills()), 0);
  for (std::size_t r = 0; r < record.diagnoses.size(); ++r) {
    const Json doc = Json::parse(record.diagnoses[r].expertise_json);
    const ExpertiseEstimate stored = expertise_from_json(JsonView(doc, "diagnosis"));
    const Json targets = Json::parse(record.diagnoses[r].targets_json);
    std::set<int> drilled;
    for (const auto& s : rounds.skills) {
      ASSERT_EQ(s.expertise.size(), 2u);
      const bool evidence = stored.occurrences[static_cast<std::size_t>(s.skill)] > 0;
      ASSERT_EQ(s.expertise[r].has_value(), evidence) << "skill " << s.skill << " round " << r + 1;
      if (evidence) {
        EXPECT_DOUBLE_EQ(*s.expertise[r], stored.expertise[static_cast<std::size_t>(s.skill)]);
        EXPECT_GE(*s.expertise[r], rounds.lowest);
      }
      if (s.drilled[r]) drilled.insert(s.skill);
      EXPECT_FALSE(s.description.empty());
    }
    // Outlined: the skills of the drills the learner played that round (the diagnosis may target more).
    const int round = record.diagnoses[r].round;
    const Json items = Json::parse(record.curricula.at(r).items_json).at("items");
    std::set<int> played;
    for (const auto* t : record.trials_of(records::TrialKind::Practice, round))
      for (const auto& m : items.at(static_cast<std::size_t>(*t->record.drill_index)).at("target_skills"))
        played.insert(m.get<int>());
    EXPECT_EQ(drilled, played) << "round " << round;
    EXPECT_FALSE(drilled.empty());
    for (int m : drilled) EXPECT_NE(std::find(targets.begin(), targets.end(), m), targets.end()) << m;
    for (int m = 0; m < stored.num_skills(); ++m)
      seen[static_cast<std::size_t>(m)] += stored.occurrences[static_cast<std::size_t>(m)] > 0;
  }
  // A skill is listed when some round has evidence for it, and only then.
  EXPECT_EQ(rounds.skills.size(),
            static_cast<std::size_t>(std::count_if(seen.begin(), seen.end(), [](int n) { return n > 0; })));
  EXPECT_LT(rounds.lowest, 0.0);  // the cut-short pre-test trial missed skills
}

}  // namespace
}  // namespace sc::review
