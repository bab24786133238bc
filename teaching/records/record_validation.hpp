#pragma once
// What every store refuses before anything is written or queued: records that could never be stored
// (empty names and timestamps, payloads that are not JSON, non-finite scores). Each check throws
// sc::InputError with one line naming the field.
#include <string_view>

#include "teaching/records/pending_writes.hpp"
#include "teaching/records/record_types.hpp"

namespace sc::records {

void require_text(std::string_view value, std::string_view what);
// A name shown on screens and in reports: not blank and free of control characters.
void require_learner_name(std::string_view name);
void validate_new_session(const NewSession& session);
void validate_trial(const TrialRecord& trial);
void validate_diagnosis(const DiagnosisRecord& diagnosis);
void validate_curriculum(const CurriculumRecord& curriculum);
void validate_progress(const SessionProgress& progress);

// The last trial number handed out for `session_id` among `pending`, or `stored_last` if larger.
int last_seq_with_pending(const std::deque<PendingWrite>& pending, std::int64_t session_id, int stored_last);
// Applies the pending writes of `point`'s session to it (trials done, progress); true when one of them
// finishes the session.
bool apply_pending_to_resume(ResumePoint& point, const std::deque<PendingWrite>& pending);

}  // namespace sc::records
