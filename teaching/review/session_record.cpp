#include "teaching/review/session_record.hpp"

#include "engine/core/error.hpp"

namespace sc::review {

const records::StoredTrial& SessionRecord::trial(int seq) const {
  for (const auto& t : trials)
    if (t.seq == seq) return t;
  throw InputError("session " + std::to_string(session.id),
                   "has no trial " + std::to_string(seq) + " (it has " + std::to_string(trials.size()) + " trials)");
}

std::vector<const records::StoredTrial*> SessionRecord::trials_of(records::TrialKind kind, int round) const {
  std::vector<const records::StoredTrial*> out;
  for (const auto& t : trials)
    if (t.record.kind == kind && (round <= 0 || t.record.round == round)) out.push_back(&t);
  return out;
}

const records::CurriculumRecord* SessionRecord::curriculum(int round) const {
  for (const auto& c : curricula)
    if (c.round == round) return &c;
  return nullptr;
}

SessionRecord load_session_record(const records::RecordStore& store, std::int64_t session_id) {
  auto session = store.session(session_id);
  if (!session) throw InputError(store.database_path().string(), "has no session " + std::to_string(session_id));
  SessionRecord record;
  record.session = std::move(*session);
  record.trials = store.trials_of_session(session_id);
  record.diagnoses = store.diagnoses_of_session(session_id);
  record.curricula = store.curricula_of_session(session_id);
  return record;
}

std::vector<std::int64_t> learner_session_ids(const records::RecordStore& store, std::string_view learner) {
  // A few names help with a typo; the whole list of a big class would make a 10 kB error line.
  constexpr std::size_t kNamesShown = 5;
  std::string names;
  std::size_t others = 0;
  for (const auto& overview : store.list_learners()) {
    if (overview.name == learner) {
      std::vector<std::int64_t> ids;
      for (const auto& s : overview.sessions) ids.push_back(s.session.id);
      return ids;
    }
    if (others++ < kNamesShown) names += (names.empty() ? "" : ", ") + overview.name;
  }
  if (others > kNamesShown) names += " and " + std::to_string(others - kNamesShown) + " more";
  throw InputError(store.database_path().string(), "has no learner '" + std::string(learner) +
                                                       "' (learners: " + (names.empty() ? "none" : names) + ")");
}

}  // namespace sc::review
