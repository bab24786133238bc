#include "teaching/records/record_studies.hpp"

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "teaching/records/record_writes.hpp"
#include "teaching/records/study_assignment.hpp"

namespace sc::records {
namespace {

constexpr std::string_view kStudyColumns = "name, task, conditions, target_per_condition, seed, created";

template <typename Row>
StudyDefinition read_study(const Row& row) {
  StudyDefinition study;
  study.name = row.column_text(0);
  study.task = row.column_text(1);
  const Json conditions = Json::parse(row.column_text(2));
  for (const auto& c : conditions) study.conditions.push_back(c.get<std::string>());
  study.target_per_condition = static_cast<int>(row.column_int(3));
  study.seed = static_cast<std::uint64_t>(row.column_int(4));
  study.created = row.column_text(5);
  return study;
}

constexpr std::string_view kParticipantSelect =
    "SELECT l.name, p.seq, p.condition, p.enrolled FROM study_participants p JOIN learners l ON l.id = p.learner_id"
    " WHERE p.study_id = (SELECT id FROM studies WHERE name = ?1)";

template <typename Row>
StudyParticipant read_participant(const Row& row) {
  return {row.column_text(0), static_cast<int>(row.column_int(1)), row.column_text(2), row.column_text(3)};
}

template <typename Db>
StudyDefinition require_study(Db& db, std::string_view name) {
  auto study = query_study(db, name);
  if (!study) throw InputError("study \"" + std::string(name) + "\"", "no such study in this database");
  return *study;
}

}  // namespace

void validate_study(const StudyDefinition& study) {
  const std::string where = "study \"" + study.name + "\"";
  if (study.name.find_first_not_of(" \t\n\r\v\f") == std::string::npos)
    throw InputError("study definition", "the study's name is blank");
  for (unsigned char c : study.name)
    if (c < 0x20 || c == 0x7f) throw InputError("study definition", "the study's name contains a control character");
  if (study.task.empty()) throw InputError(where, "has no task");
  if (study.created.empty()) throw InputError(where, "has no creation time");
  if (study.conditions.size() < 2) throw InputError(where, "needs at least two conditions to compare");
  for (std::size_t i = 0; i < study.conditions.size(); ++i) {
    if (study.conditions[i].empty()) throw InputError(where, "has an empty condition name");
    for (std::size_t j = 0; j < i; ++j)
      if (study.conditions[i] == study.conditions[j])
        throw InputError(where, "names the condition \"" + study.conditions[i] + "\" twice");
  }
  if (study.target_per_condition < 1 || study.target_per_condition > 10000)
    throw InputError(where, "participants per condition must be between 1 and 10000");
}

template <typename Db>
void insert_study(Db& db, const StudyDefinition& study) {
  if (query_study(db, study.name))
    throw InputError("study \"" + study.name + "\"", "already exists in this database; choose another name");
  db.prepare("INSERT INTO studies(" + std::string(kStudyColumns) + ") VALUES(?1, ?2, ?3, ?4, ?5, ?6)")
      .bind(1, study.name)
      .bind(2, study.task)
      .bind(3, Json(study.conditions).dump())
      .bind(4, std::int64_t{study.target_per_condition})
      .bind(5, static_cast<std::int64_t>(study.seed))  // bit pattern kept; read back as unsigned
      .bind(6, study.created)
      .run();
}

template <typename Db>
std::optional<StudyDefinition> query_study(Db& db, std::string_view name) {
  auto stmt = db.prepare("SELECT " + std::string(kStudyColumns) + " FROM studies WHERE name = ?1");
  stmt.bind(1, name);
  if (!stmt.step()) return std::nullopt;
  return read_study(stmt);
}

template <typename Db>
std::vector<StudyDefinition> query_studies(Db& db) {
  auto stmt = db.prepare("SELECT " + std::string(kStudyColumns) + " FROM studies ORDER BY name");
  std::vector<StudyDefinition> out;
  while (stmt.step()) out.push_back(read_study(stmt));
  return out;
}

template <typename Db>
std::vector<StudyParticipant> query_participants(Db& db, std::string_view study) {
  auto stmt = db.prepare(std::string(kParticipantSelect) + " ORDER BY p.seq");
  stmt.bind(1, study);
  std::vector<StudyParticipant> out;
  while (stmt.step()) out.push_back(read_participant(stmt));
  return out;
}

template <typename Db>
std::optional<StudyParticipant> query_participant(Db& db, std::string_view study, std::string_view learner) {
  auto stmt = db.prepare(std::string(kParticipantSelect) + " AND l.name = ?2");
  stmt.bind(1, study).bind(2, learner);
  if (!stmt.step()) return std::nullopt;
  return read_participant(stmt);
}

template <typename Db>
StudyParticipant enrol_participant(Db& db, std::string_view study_name, std::string_view learner,
                                   std::string_view enrolled) {
  const StudyDefinition study = require_study(db, study_name);
  if (auto existing = query_participant(db, study_name, learner)) return *existing;
  auto count =
      db.prepare("SELECT count(*) FROM study_participants WHERE study_id = (SELECT id FROM studies WHERE name = ?1)");
  count.bind(1, study_name).step();
  const int enrolled_so_far = static_cast<int>(count.column_int(0));
  count.run();
  if (enrolled_so_far >= study.capacity()) {
    throw InputError("study \"" + study.name + "\"", "is full: all " + std::to_string(study.capacity()) + " places (" +
                                                         std::to_string(study.target_per_condition) +
                                                         " per condition) are taken; \"" + std::string(learner) +
                                                         "\" was not enrolled");
  }
  const StudyParticipant participant{std::string(learner), enrolled_so_far + 1,
                                     assignment_sequence(study)[static_cast<std::size_t>(enrolled_so_far)],
                                     std::string(enrolled)};
  const std::int64_t learner_id = insert_learner_if_new(db, learner, enrolled);
  db.prepare(
        "INSERT INTO study_participants(study_id, learner_id, seq, condition, enrolled)"
        " VALUES((SELECT id FROM studies WHERE name = ?1), ?2, ?3, ?4, ?5)")
      .bind(1, study_name)
      .bind(2, learner_id)
      .bind(3, std::int64_t{participant.seq})
      .bind(4, participant.condition)
      .bind(5, participant.enrolled)
      .run();
  return participant;
}

template <typename Db>
void attach_session_to_study(Db& db, std::int64_t session_id, const NewSession& session) {
  const StudyDefinition study = require_study(db, session.study);
  const std::string where = "study \"" + study.name + "\"";
  const auto participant = query_participant(db, study.name, session.learner);
  if (!participant) throw InputError(where, "\"" + session.learner + "\" is not enrolled (enrol them first)");
  if (session.task != study.task)
    throw InputError(where, "is a " + study.task + " study; a " + session.task + " session cannot join it");
  if (session.condition != participant->condition)
    throw InputError(where, "\"" + session.learner + "\" was assigned another condition than the session's");
  db.prepare("UPDATE sessions SET study_id = (SELECT id FROM studies WHERE name = ?1) WHERE id = ?2")
      .bind(1, study.name)
      .bind(2, session_id)
      .run();
}

std::vector<ConditionEnrolment> enrolment_by_condition(const StudyDefinition& study,
                                                       const std::vector<StudyParticipant>& participants) {
  std::vector<ConditionEnrolment> out;
  for (const std::string& condition : study.conditions) {
    ConditionEnrolment row{condition, 0, study.target_per_condition};
    for (const StudyParticipant& p : participants) row.enrolled += p.condition == condition ? 1 : 0;
    out.push_back(row);
  }
  return out;
}

// The record SQL runs on both stores (pg_handle.hpp has the same shape as sqlite_handle.hpp).
template void insert_study(SqliteDb& db, const StudyDefinition& study);
template std::optional<StudyDefinition> query_study(SqliteDb& db, std::string_view name);
template std::vector<StudyDefinition> query_studies(SqliteDb& db);
template std::vector<StudyParticipant> query_participants(SqliteDb& db, std::string_view study);
template std::optional<StudyParticipant> query_participant(SqliteDb& db, std::string_view study,
                                                           std::string_view learner);
template StudyParticipant enrol_participant(SqliteDb& db, std::string_view study, std::string_view learner,
                                            std::string_view enrolled);
template void attach_session_to_study(SqliteDb& db, std::int64_t session_id, const NewSession& session);
template void insert_study(PgDb& db, const StudyDefinition& study);
template std::optional<StudyDefinition> query_study(PgDb& db, std::string_view name);
template std::vector<StudyDefinition> query_studies(PgDb& db);
template std::vector<StudyParticipant> query_participants(PgDb& db, std::string_view study);
template std::optional<StudyParticipant> query_participant(PgDb& db, std::string_view study, std::string_view learner);
template StudyParticipant enrol_participant(PgDb& db, std::string_view study, std::string_view learner,
                                            std::string_view enrolled);
template void attach_session_to_study(PgDb& db, std::int64_t session_id, const NewSession& session);

}  // namespace sc::records
