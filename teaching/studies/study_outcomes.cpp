#include "teaching/studies/study_outcomes.hpp"

namespace sc {
namespace {

ParticipantOutcome outcome_of(const records::StudyParticipant& participant,
                              const std::vector<records::SessionSummary>& sessions) {
  ParticipantOutcome out{participant, {}, {}, {}, {}, 0, {}};
  const records::SessionSummary* first = nullptr;
  for (const auto& s : sessions) {  // oldest first
    if (s.session.learner != participant.learner) continue;
    if (first == nullptr) {
      first = &s;
    } else {
      ++out.later_sessions;
    }
  }
  if (first == nullptr) {
    out.excluded = "no session yet";
    return out;
  }
  out.session_id = first->session.id;
  out.pretest_mean = first->pretest_mean;
  out.eval_mean = first->eval_mean;
  out.improvement = first->improvement;
  const std::string which = "session " + std::to_string(first->session.id);
  if (!first->session.finished) {
    out.excluded = which + " is unfinished";
  } else if (!first->pretest_mean) {
    out.excluded = which + " has no pre-test score";
  } else if (!first->eval_mean) {
    out.excluded = which + " has no evaluation score";
  }
  return out;
}

}  // namespace

std::vector<ParticipantOutcome> participant_outcomes(const std::vector<records::StudyParticipant>& participants,
                                                     const std::vector<records::SessionSummary>& sessions) {
  std::vector<ParticipantOutcome> out;
  out.reserve(participants.size());
  for (const auto& p : participants) out.push_back(outcome_of(p, sessions));
  return out;
}

}  // namespace sc
