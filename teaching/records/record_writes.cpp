#include "teaching/records/record_writes.hpp"

#include <string>

namespace sc::records {
namespace {

template <typename Db>
void update_progress(Db& db, std::int64_t session_id, const SessionProgress& progress) {
  db.prepare("UPDATE sessions SET round = ?1, phase = ?2, item_index = ?3 WHERE id = ?4")
      .bind(1, std::int64_t{progress.round})
      .bind(2, to_string(progress.phase))
      .bind(3, std::int64_t{progress.item_index})
      .bind(4, session_id)
      .run();
}

// The seq is taken: a replay of this very trial (the spill file of a store whose commit did land) is fine;
// another trial under that number means a second trainer wrote to the session, and merging the two
// silently would lose one of them, so the write fails and stays pending.
template <typename Db>
void require_same_trial(Db& db, const TrialWrite& write) {
  auto existing = db.prepare("SELECT started, trajectory FROM trials WHERE session_id = ?1 AND seq = ?2");
  existing.bind(1, write.trial.session_id).bind(2, std::int64_t{write.seq});
  const bool same = existing.step() && existing.column_text(0) == write.trial.started &&
                    existing.column_text(1) == write.trial.trajectory_json;
  existing.run();
  if (!same) {
    db.fail_conflict("trial " + std::to_string(write.seq) + " of session " + std::to_string(write.trial.session_id) +
                     " is already a different trial (another trainer wrote to this session)");
  }
}

template <typename Db>
void insert_trial(Db& db, const TrialWrite& write) {
  const TrialRecord& t = write.trial;
  db.prepare(
        "INSERT INTO trials(session_id, seq, kind, round, drill_index, task, scenario, trajectory, score, device,"
        " started, finished) VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12)"
        " ON CONFLICT(session_id, seq) DO NOTHING")
      .bind(1, t.session_id)
      .bind(2, std::int64_t{write.seq})
      .bind(3, to_string(t.kind))
      .bind(4, std::int64_t{t.round})
      .bind(5, t.drill_index ? std::optional<std::int64_t>(*t.drill_index) : std::nullopt)
      .bind(6, t.task)
      .bind(7, t.scenario_json)
      .bind(8, t.trajectory_json)
      .bind(9, t.score)
      .bind(10, t.device)
      .bind(11, t.started)
      .bind(12, t.finished)
      .run();
  if (db.changes() == 0) require_same_trial(db, write);
  if (t.progress_after) update_progress(db, t.session_id, *t.progress_after);
}

template <typename Db>
void upsert_diagnosis(Db& db, const DiagnosisRecord& d) {
  db.prepare(
        "INSERT INTO diagnoses(session_id, round, expertise, targets, extractor, model_id, created)"
        " VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7) ON CONFLICT(session_id, round) DO UPDATE SET"
        " expertise = excluded.expertise, targets = excluded.targets, extractor = excluded.extractor,"
        " model_id = excluded.model_id, created = excluded.created")
      .bind(1, d.session_id)
      .bind(2, std::int64_t{d.round})
      .bind(3, d.expertise_json)
      .bind(4, d.targets_json)
      .bind(5, d.extractor)
      .bind(6, d.model_id)
      .bind(7, d.created)
      .run();
}

template <typename Db>
void upsert_curriculum(Db& db, const CurriculumRecord& c) {
  auto upsert = db.prepare(
      "INSERT INTO curricula(session_id, round, condition, items, created) VALUES(?1, ?2, ?3, ?4, ?5)"
      " ON CONFLICT(session_id, round) DO UPDATE SET condition = excluded.condition, items = excluded.items,"
      " created = excluded.created RETURNING id");
  upsert.bind(1, c.session_id).bind(2, std::int64_t{c.round}).bind(3, c.condition).bind(4, c.items_json);
  upsert.bind(5, c.created);
  upsert.step();
  const std::int64_t curriculum_id = upsert.column_int(0);
  upsert.run();  // finish the statement before the next one
  db.prepare("DELETE FROM drills WHERE curriculum_id = ?1").bind(1, curriculum_id).run();
  auto insert = db.prepare("INSERT INTO drills(curriculum_id, idx, skills, content) VALUES(?1, ?2, ?3, ?4)");
  for (const auto& drill : c.drills) {
    insert.bind(1, curriculum_id).bind(2, std::int64_t{drill.index}).bind(3, drill.skills_json);
    insert.bind(4, drill.content_json).run();
  }
}

}  // namespace

template <typename Db>
std::int64_t insert_learner_if_new(Db& db, std::string_view name, std::string_view created) {
  db.prepare("INSERT INTO learners(name, created) VALUES(?1, ?2) ON CONFLICT(name) DO NOTHING")
      .bind(1, name)
      .bind(2, created)
      .run();
  auto select = db.prepare("SELECT id FROM learners WHERE name = ?1");
  select.bind(1, name);
  select.step();
  return select.column_int(0);
}

template <typename Db>
std::int64_t insert_session(Db& db, std::int64_t learner_id, const NewSession& s) {
  auto insert = db.prepare(
      "INSERT INTO sessions(learner_id, task, condition, seed, settings, started) VALUES(?1, ?2, ?3, ?4, ?5, ?6)"
      " RETURNING id");
  insert.bind(1, learner_id)
      .bind(2, s.task)
      .bind(3, s.condition)
      .bind(4, static_cast<std::int64_t>(s.seed))  // bit pattern kept; read back as unsigned
      .bind(5, s.settings_json)
      .bind(6, s.started)
      .step();
  const std::int64_t id = insert.column_int(0);
  insert.run();  // finish the statement
  return id;
}

template <typename Db>
void apply_write(Db& db, const PendingWrite& write) {
  std::visit(
      [&db](const auto& w) {
        using T = std::decay_t<decltype(w)>;
        if constexpr (std::is_same_v<T, TrialWrite>) insert_trial(db, w);
        if constexpr (std::is_same_v<T, DiagnosisRecord>) upsert_diagnosis(db, w);
        if constexpr (std::is_same_v<T, CurriculumRecord>) upsert_curriculum(db, w);
        if constexpr (std::is_same_v<T, ProgressWrite>) update_progress(db, w.session_id, w.progress);
        if constexpr (std::is_same_v<T, FinishWrite>)
          db.prepare("UPDATE sessions SET finished = ?1 WHERE id = ?2").bind(1, w.finished).bind(2, w.session_id).run();
      },
      write);
}

// The record SQL runs on both stores (pg_handle.hpp has the same shape as sqlite_handle.hpp).
template std::int64_t insert_learner_if_new(SqliteDb& db, std::string_view name, std::string_view created);
template std::int64_t insert_session(SqliteDb& db, std::int64_t learner_id, const NewSession& session);
template void apply_write(SqliteDb& db, const PendingWrite& write);
template std::int64_t insert_learner_if_new(PgDb& db, std::string_view name, std::string_view created);
template std::int64_t insert_session(PgDb& db, std::int64_t learner_id, const NewSession& session);
template void apply_write(PgDb& db, const PendingWrite& write);

}  // namespace sc::records
