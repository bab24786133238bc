// Resuming a session after a crash or a closed window: the database holds the settings, every finished
// trial and the point to resume from; the pre-test selection, diagnoses and curricula are recomputed from
// them (all deterministic in the seed), so nothing but the trials themselves has to be trusted.
#include "engine/core/error.hpp"
#include "teaching/sessions/training_session.hpp"

namespace sc {

std::unique_ptr<TrainingSession> TrainingSession::resume(const TaskKit& kit, records::RecordStore& store,
                                                         const records::ResumePoint& point, TimestampSource now) {
  const records::SessionRow& row = point.session;
  const std::string where = "session " + std::to_string(row.id);
  if (row.task != kit.task()) throw InputError(where, "is a " + row.task + " session, not " + kit.task());
  std::unique_ptr<TrainingSession> s(new TrainingSession(kit, store, std::move(now)));
  s->session_id_ = row.id;
  s->settings_ = settings_of_session(row);
  s->select_pretest();
  s->rounds_.resize(1);

  for (const records::StoredTrial& stored : store.trials_of_session(row.id)) {
    const records::TrialRecord& t = stored.record;
    const std::string trial_where = where + " trial " + std::to_string(stored.seq);
    Json trial = parse_json_text(t.trajectory_json, trial_where);
    if (t.round < 1 || t.round > row.progress.round) throw InputError(trial_where, "belongs to a later round");
    switch (t.kind) {
      case records::TrialKind::Pretest:
        if (s->pretest_trials_.size() >= s->pretest_pool_.size())
          throw InputError(trial_where, "is one pre-test trial too many");
        s->pretest_trials_.push_back(std::move(trial));
        break;
      case records::TrialKind::Demo:
        break;  // demos carry no evidence
      case records::TrialKind::Practice: {
        if (!s->state(t.round).analysed) s->compute_round(t.round);
        const int items = static_cast<int>(s->state(t.round).curriculum.items.size());
        if (!t.drill_index || *t.drill_index < 0 || *t.drill_index >= items)
          throw InputError(trial_where, "names a practice item the round's curriculum does not have");
        s->state(t.round).practice.emplace_back(*t.drill_index, std::move(trial));
        break;
      }
      case records::TrialKind::Eval:
        s->state(t.round).eval.push_back(std::move(trial));
        break;
    }
  }
  s->progress_ = row.progress;
  s->state(s->round());
  // Rounds before the current one, and the current one once past its diagnosis, need their curricula.
  for (int r = 1; r <= s->round(); ++r) {
    const bool needed = r < s->round() || s->phase() != SessionPhase::Diagnosis;
    const bool pretest_round = r == 1 && s->phase() == SessionPhase::Pretest;
    if (needed && !pretest_round && !s->state(r).analysed) s->compute_round(r);
  }
  return s;
}

}  // namespace sc
