// Studies in the learner store: definitions, enrolment in the randomisation's order, a full study refusing,
// sessions joining only their participant's assigned condition, and a version-1 database upgraded to
// studies with its data intact.
#include "teaching/records/record_studies.hpp"

#include <array>

#include <gtest/gtest.h>

#include "teaching/records/schema_migrations.hpp"
#include "teaching/records/study_assignment.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

StudyDefinition pilot(int per_condition = 2) {
  return {"pilot",
          "parking",
          {"skills", "time-heuristic", "full-trajectory"},
          per_condition,
          0xfedcba9876543210ULL,
          "2024-05-01T09:00:00.000Z"};
}

NewSession study_session(const std::string& learner, const std::string& condition,
                         const std::string& task = "parking") {
  return {learner, task, condition, 5u, "{}", "2024-05-01T10:00:00.000Z", "pilot"};
}

TEST(RecordStudies, DefinitionRoundTripsAndNamesAreUnique) {
  LearnerStore store(test::fresh_dir("study-define"));
  store.create_study(pilot());
  const auto back = store.study("pilot");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->task, "parking");
  EXPECT_EQ(back->conditions, pilot().conditions);
  EXPECT_EQ(back->target_per_condition, 2);
  EXPECT_EQ(back->seed, 0xfedcba9876543210ULL);  // the full 64-bit pattern
  EXPECT_FALSE(store.study("other"));
  EXPECT_EQ(test::error_of([&] { store.create_study(pilot()); }),
            "study \"pilot\": already exists in this database; choose another name");
  auto one = pilot();
  one.name = "one";
  one.conditions = {"skills"};
  EXPECT_EQ(test::error_of([&] { store.create_study(one); }),
            "study \"one\": needs at least two conditions to compare");
  one.conditions = {"skills", "drills", "skills"};
  EXPECT_EQ(test::error_of([&] { store.create_study(one); }), "study \"one\": names the condition \"skills\" twice");
  EXPECT_EQ(store.list_studies().size(), 1u);
}

TEST(RecordStudies, EnrolmentFollowsTheSequenceAndAFullStudyRefuses) {
  LearnerStore store(test::fresh_dir("study-enrol"));
  store.create_study(pilot());
  const auto sequence = assignment_sequence(pilot());
  for (int i = 0; i < 6; ++i) {
    const auto p = store.enrol("pilot", "P" + std::to_string(i), "2024-05-01T10:00:00.000Z");
    EXPECT_EQ(p.seq, i + 1);
    EXPECT_EQ(p.condition, sequence[static_cast<std::size_t>(i)]);
  }
  // Enrolling again keeps the place and the condition.
  EXPECT_EQ(store.enrol("pilot", "P3", "2024-05-02T10:00:00.000Z").seq, 4);
  EXPECT_EQ(test::error_of([&] { store.enrol("pilot", "late", "2024-05-01T10:00:00.000Z"); }),
            "study \"pilot\": is full: all 6 places (2 per condition) are taken; \"late\" was not enrolled");
  EXPECT_EQ(test::error_of([&] { store.enrol("nope", "P9", "2024-05-01T10:00:00.000Z"); }),
            "study \"nope\": no such study in this database");
  const auto participants = store.study_participants("pilot");
  ASSERT_EQ(participants.size(), 6u);
  for (const auto& row : enrolment_by_condition(pilot(), participants)) {
    EXPECT_EQ(row.enrolled, 2) << row.condition;
    EXPECT_EQ(row.target, 2);
  }
}

TEST(RecordStudies, ASessionJoinsOnlyWithItsParticipantsAssignment) {
  LearnerStore store(test::fresh_dir("study-session"));
  store.create_study(pilot());
  EXPECT_EQ(test::error_of([&] { store.begin_session(study_session("stranger", "skills")); }),
            "study \"pilot\": \"stranger\" is not enrolled (enrol them first)");
  const auto p = store.enrol("pilot", "Ada", "2024-05-01T10:00:00.000Z");
  const std::string other = p.condition == "skills" ? "drills" : "skills";
  EXPECT_EQ(test::error_of([&] { store.begin_session(study_session("Ada", other)); }),
            "study \"pilot\": \"Ada\" was assigned another condition than the session's");
  EXPECT_EQ(test::error_of([&] { store.begin_session(study_session("Ada", p.condition, "writing")); }),
            "study \"pilot\": is a parking study; a writing session cannot join it");
  EXPECT_TRUE(store.list_learners().front().sessions.empty());  // refused sessions leave nothing behind
  const auto id = store.begin_session(study_session("Ada", p.condition));
  store.record_trial(test::sample_trial(id, 0, TrialKind::Pretest, -2.0));
  auto eval = test::sample_trial(id, 1, TrialKind::Eval, -0.5);
  store.record_trial(eval);
  store.finish_session(id, "2024-05-01T11:00:00.000Z");
  store.begin_session(test::sample_session("Ada"));  // a session outside the study
  EXPECT_EQ(store.session(id)->study, "pilot");
  const auto sessions = store.study_sessions("pilot");
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_EQ(sessions[0].session.id, id);
  EXPECT_DOUBLE_EQ(*sessions[0].improvement, 1.5);
}

void make_version1_database(const std::filesystem::path& dir) {
  SqliteDb db(dir / "skillcoach.db", SqliteDb::Mode::ReadWriteCreate);
  migrate(db, schema_migrations().first(1), "v1");
  db.exec(
      "INSERT INTO learners(name, created) VALUES('Ada', '2024-05-01T10:00:00.000Z');"
      "INSERT INTO sessions(learner_id, task, condition, seed, started) VALUES(1, 'parking', 'skills', 3,"
      " '2024-05-01T10:00:00.000Z')");
}

// Export, report and review open read-only: they read an older database as if upgraded, and leave the file
// exactly as it was (the next writable open upgrades it).
TEST(RecordStudies, AVersion1DatabaseIsReadWithoutChangingIt) {
  const auto dir = test::fresh_dir("study-read-v1");
  make_version1_database(dir);
  const std::string before = test::file_bytes(dir / "skillcoach.db");
  {
    const LearnerStore store(dir, StoreOptions{.read_only = true});
    EXPECT_EQ(store.schema_version(), 2);
    ASSERT_EQ(store.list_learners().size(), 1u);
    EXPECT_EQ(store.list_learners()[0].sessions[0].session.condition, "skills");
    EXPECT_TRUE(store.list_studies().empty());
  }
  EXPECT_EQ(test::file_bytes(dir / "skillcoach.db"), before);
}

TEST(RecordStudies, AVersion1DatabaseIsUpgradedWithItsData) {
  const auto dir = test::fresh_dir("study-upgrade");
  make_version1_database(dir);
  ASSERT_EQ(SqliteDb(dir / "skillcoach.db", SqliteDb::Mode::ReadWriteCreate).query_int("PRAGMA user_version"), 1);
  LearnerStore store(dir);
  EXPECT_EQ(store.schema_version(), 2);
  const auto learners = store.list_learners();
  ASSERT_EQ(learners.size(), 1u);
  ASSERT_EQ(learners[0].sessions.size(), 1u);
  EXPECT_EQ(learners[0].sessions[0].session.condition, "skills");
  EXPECT_EQ(learners[0].sessions[0].session.study, "");
  store.create_study(pilot());  // the new tables work on the upgraded file
  EXPECT_EQ(store.enrol("pilot", "Ada", "2024-05-02T10:00:00.000Z").seq, 1);
}

}  // namespace
}  // namespace sc::records
