#pragma once
// JSON form of the learner records, shared by the export (`skillcoach export`) and the pending-writes
// spill file. JSON payload columns (scenario, trajectory, expertise, ...) are embedded as JSON values, not
// strings, so an exported trial's "trajectory" is a trajectory-file document as it stands.
#include "engine/core/json_file.hpp"
#include "teaching/records/record_types.hpp"

namespace sc::records {

Json progress_to_json(const SessionProgress& progress);
SessionProgress progress_from_json(const JsonView& node);

// `seq` is the trial's 1-based position in its session.
Json trial_to_json(const TrialRecord& trial, int seq);
TrialRecord trial_from_json(const JsonView& node);
int trial_seq_from_json(const JsonView& node);

Json diagnosis_to_json(const DiagnosisRecord& diagnosis);
DiagnosisRecord diagnosis_from_json(const JsonView& node);

Json curriculum_to_json(const CurriculumRecord& curriculum);
CurriculumRecord curriculum_from_json(const JsonView& node);

Json session_to_json(const SessionRow& session);

// Parses a payload column that the database guarantees to be valid JSON.
Json payload(const std::string& text);

}  // namespace sc::records
