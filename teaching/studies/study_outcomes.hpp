#pragma once
// Each participant's outcome, the paper's measure: reward improvement = mean evaluation reward - mean
// pre-test reward of their session (the pre-test of the first round, the evaluation of the last round that
// has one; records::SessionSummary). Which session counts is fixed in advance, not chosen by its result:
// the participant's first session in the study. It counts when it is finished and has both pre-test and
// evaluation scores; otherwise the participant is listed with the reason and left out of the statistics.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "teaching/records/record_types.hpp"
#include "teaching/records/study_records.hpp"

namespace sc {

struct ParticipantOutcome {
  records::StudyParticipant participant;
  std::optional<std::int64_t> session_id;  // the session that counts (the first one in the study)
  std::optional<double> pretest_mean, eval_mean, improvement;
  int later_sessions = 0;  // further sessions of this participant in the study (ignored)
  std::string excluded;    // empty when counted; otherwise why not ("no session yet", ...)

  bool counted() const { return excluded.empty(); }
};

// In enrolment order. `sessions` are the study's sessions (LearnerStore::study_sessions).
std::vector<ParticipantOutcome> participant_outcomes(const std::vector<records::StudyParticipant>& participants,
                                                     const std::vector<records::SessionSummary>& sessions);

}  // namespace sc
