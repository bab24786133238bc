#pragma once
// The SQL of studies: defining one, enrolling a participant (the assignment is taken inside the caller's
// write transaction, so two enrolments never get one place), and reading enrolment back. Plain records in,
// plain records out, so another store can implement the same functions.
#include <optional>
#include <string_view>
#include <vector>

#include "teaching/records/pg_handle.hpp"
#include "teaching/records/record_types.hpp"
#include "teaching/records/sqlite_handle.hpp"
#include "teaching/records/study_records.hpp"

namespace sc::records {

// A study must be able to compare conditions: a name, a task, two or more distinct conditions and 1 to 10000
// participants per condition; sc::InputError otherwise.
void validate_study(const StudyDefinition& study);
// Throws sc::InputError when a study of that name exists.
template <typename Db>
void insert_study(Db& db, const StudyDefinition& study);
template <typename Db>
std::optional<StudyDefinition> query_study(Db& db, std::string_view name);
template <typename Db>
std::vector<StudyDefinition> query_studies(Db& db);  // by name
template <typename Db>
std::vector<StudyParticipant> query_participants(Db& db, std::string_view study);  // by seq
template <typename Db>
std::optional<StudyParticipant> query_participant(Db& db, std::string_view study, std::string_view learner);
// Enrols `learner` (created if new) as the next participant with the next condition of the study's
// assignment sequence; an enrolled learner keeps their place. Throws sc::InputError for an unknown or full
// study.
template <typename Db>
StudyParticipant enrol_participant(Db& db, std::string_view study, std::string_view learner, std::string_view enrolled);
// Sets the new session's study; throws sc::InputError unless the learner is enrolled in it and the
// session's task and condition are the study's task and the learner's assigned condition.
template <typename Db>
void attach_session_to_study(Db& db, std::int64_t session_id, const NewSession& session);

// Enrolment per condition of `participants` against the study's target, in the study's condition order.
std::vector<ConditionEnrolment> enrolment_by_condition(const StudyDefinition& study,
                                                       const std::vector<StudyParticipant>& participants);

}  // namespace sc::records
