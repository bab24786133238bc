#pragma once
// Everything the database holds about one session, read once for the review (the store is opened
// read-only by the callers: the review never writes).
#include <cstdint>
#include <string_view>
#include <vector>

#include "teaching/records/learner_store.hpp"

namespace sc::review {

struct SessionRecord {
  records::SessionRow session;
  std::vector<records::StoredTrial> trials;          // seq order
  std::vector<records::DiagnosisRecord> diagnoses;   // by round
  std::vector<records::CurriculumRecord> curricula;  // by round

  // The trial with that seq; throws InputError naming the session when there is none.
  const records::StoredTrial& trial(int seq) const;
  // Trials of one kind (and one round, if round > 0), in seq order.
  std::vector<const records::StoredTrial*> trials_of(records::TrialKind kind, int round = 0) const;
  const records::CurriculumRecord* curriculum(int round) const;  // nullptr if that round has none
};

// Throws InputError naming the database for an unknown session id.
SessionRecord load_session_record(const records::RecordStore& store, std::int64_t session_id);

// The ids of a learner's sessions (oldest first); throws InputError naming the database for an unknown
// learner, listing the learners it does hold.
std::vector<std::int64_t> learner_session_ids(const records::RecordStore& store, std::string_view learner);

}  // namespace sc::review
