#include "teaching/records/record_queries.hpp"

#include <map>

namespace sc::records {
namespace {

constexpr std::string_view kSessionColumns =
    "s.id, l.name, s.task, s.condition, s.seed, s.settings, s.started, s.finished, s.round, s.phase, s.item_index,"
    " (SELECT name FROM studies WHERE id = s.study_id)";

template <typename Row>
SessionRow read_session(const Row& row) {
  SessionRow s;
  s.id = row.column_int(0);
  s.learner = row.column_text(1);
  s.task = row.column_text(2);
  s.condition = row.column_text(3);
  s.seed = static_cast<std::uint64_t>(row.column_int(4));
  s.settings_json = row.column_text(5);
  s.started = row.column_text(6);
  if (!row.column_is_null(7)) s.finished = row.column_text(7);
  s.progress.round = static_cast<int>(row.column_int(8));
  s.progress.phase = session_phase_from_string(row.column_text(9), "sessions.phase");
  s.progress.item_index = static_cast<int>(row.column_int(10));
  if (!row.column_is_null(11)) s.study = row.column_text(11);
  return s;
}

std::string session_select(std::string_view where) {
  return "SELECT " + std::string(kSessionColumns) + " FROM sessions s JOIN learners l ON l.id = s.learner_id " +
         std::string(where);
}

// Pre-test mean: first round's pre-test; evaluation mean: the last round that has an evaluation.
constexpr std::string_view kSummaryColumns =
    ", (SELECT count(*) FROM trials t WHERE t.session_id = s.id),"
    " (SELECT avg(score) FROM trials t WHERE t.session_id = s.id AND t.kind = 'pretest' AND t.round ="
    "   (SELECT min(round) FROM trials u WHERE u.session_id = s.id AND u.kind = 'pretest')),"
    " (SELECT avg(score) FROM trials t WHERE t.session_id = s.id AND t.kind = 'eval' AND t.round ="
    "   (SELECT max(round) FROM trials u WHERE u.session_id = s.id AND u.kind = 'eval')),"
    " s.learner_id FROM sessions s JOIN learners l ON l.id = s.learner_id ";

struct LearnerSessionSummary {
  std::int64_t learner_id = 0;
  SessionSummary summary;
};

// Sessions matching `where` (may bind ?1 to `text`), oldest first, with their review summaries.
template <typename Db>
std::vector<LearnerSessionSummary> query_session_summaries(Db& db, std::string_view where, std::string_view text = {}) {
  auto stmt = db.prepare("SELECT " + std::string(kSessionColumns) + std::string(kSummaryColumns) + std::string(where) +
                         " ORDER BY s.started, s.id");
  if (!text.empty()) stmt.bind(1, text);
  std::vector<LearnerSessionSummary> out;
  while (stmt.step()) {
    SessionSummary summary;
    summary.session = read_session(stmt);
    summary.trial_count = static_cast<int>(stmt.column_int(12));
    summary.pretest_mean = stmt.column_optional_double(13);
    summary.eval_mean = stmt.column_optional_double(14);
    if (summary.pretest_mean && summary.eval_mean) summary.improvement = *summary.eval_mean - *summary.pretest_mean;
    out.push_back({stmt.column_int(15), std::move(summary)});
  }
  return out;
}

}  // namespace

template <typename Db>
std::optional<SessionRow> query_session(Db& db, std::int64_t session_id) {
  auto stmt = db.prepare(session_select("WHERE s.id = ?1"));
  stmt.bind(1, session_id);
  if (!stmt.step()) return std::nullopt;
  return read_session(stmt);
}

template <typename Db>
std::vector<SessionRow> query_unfinished_sessions(Db& db, std::string_view learner, std::string_view task) {
  auto stmt = db.prepare(session_select(
      "WHERE l.name = ?1 AND (?2 = '' OR s.task = ?2) AND s.finished IS NULL ORDER BY s.started DESC, s.id DESC"));
  stmt.bind(1, learner).bind(2, task);
  std::vector<SessionRow> out;
  while (stmt.step()) out.push_back(read_session(stmt));
  return out;
}

template <typename Db>
int query_session_count(Db& db, std::string_view learner, std::string_view task) {
  auto stmt = db.prepare(
      "SELECT count(*) FROM sessions s JOIN learners l ON l.id = s.learner_id WHERE l.name = ?1 AND s.task = ?2");
  stmt.bind(1, learner).bind(2, task).step();
  return static_cast<int>(stmt.column_int(0));
}

template <typename Db>
int query_trial_count(Db& db, std::int64_t session_id) {
  auto stmt = db.prepare("SELECT count(*) FROM trials WHERE session_id = ?1");
  stmt.bind(1, session_id).step();
  return static_cast<int>(stmt.column_int(0));
}

template <typename Db>
int query_last_seq(Db& db, std::int64_t session_id) {
  auto stmt = db.prepare("SELECT coalesce(max(seq), 0) FROM trials WHERE session_id = ?1");
  stmt.bind(1, session_id).step();
  return static_cast<int>(stmt.column_int(0));
}

template <typename Db>
std::vector<LearnerOverview> query_learners(Db& db) {
  std::vector<LearnerOverview> learners;
  std::map<std::int64_t, std::size_t> by_id;
  auto list = db.prepare("SELECT id, name, created FROM learners ORDER BY lower(name), id");
  while (list.step()) {
    by_id[list.column_int(0)] = learners.size();
    learners.push_back({list.column_int(0), list.column_text(1), list.column_text(2), {}});
  }
  for (auto& row : query_session_summaries(db, ""))
    learners[by_id.at(row.learner_id)].sessions.push_back(std::move(row.summary));
  return learners;
}

template <typename Db>
std::vector<StoredTrial> query_trials(Db& db, std::int64_t session_id) {
  auto stmt = db.prepare(
      "SELECT id, seq, kind, round, drill_index, task, scenario, trajectory, score, device, started, finished"
      " FROM trials WHERE session_id = ?1 ORDER BY seq");
  stmt.bind(1, session_id);
  std::vector<StoredTrial> out;
  while (stmt.step()) {
    StoredTrial row;
    row.id = stmt.column_int(0);
    row.seq = static_cast<int>(stmt.column_int(1));
    TrialRecord& t = row.record;
    t.session_id = session_id;
    t.kind = trial_kind_from_string(stmt.column_text(2), "trials.kind");
    t.round = static_cast<int>(stmt.column_int(3));
    if (auto drill = stmt.column_optional_int(4)) t.drill_index = static_cast<int>(*drill);
    t.task = stmt.column_text(5);
    t.scenario_json = stmt.column_text(6);
    t.trajectory_json = stmt.column_text(7);
    t.score = stmt.column_optional_double(8);
    t.device = stmt.column_text(9);
    t.started = stmt.column_text(10);
    t.finished = stmt.column_text(11);
    out.push_back(std::move(row));
  }
  return out;
}

template <typename Db>
std::vector<DiagnosisRecord> query_diagnoses(Db& db, std::int64_t session_id) {
  auto stmt = db.prepare(
      "SELECT round, expertise, targets, extractor, model_id, created FROM diagnoses WHERE session_id = ?1"
      " ORDER BY round");
  stmt.bind(1, session_id);
  std::vector<DiagnosisRecord> out;
  while (stmt.step()) {
    out.push_back({session_id, static_cast<int>(stmt.column_int(0)), stmt.column_text(1), stmt.column_text(2),
                   stmt.column_text(3), stmt.column_text(4), stmt.column_text(5)});
  }
  return out;
}

template <typename Db>
std::vector<CurriculumRecord> query_curricula(Db& db, std::int64_t session_id) {
  auto stmt =
      db.prepare("SELECT id, round, condition, items, created FROM curricula WHERE session_id = ?1 ORDER BY round");
  stmt.bind(1, session_id);
  auto drills = db.prepare("SELECT idx, skills, content FROM drills WHERE curriculum_id = ?1 ORDER BY idx");
  std::vector<CurriculumRecord> out;
  while (stmt.step()) {
    CurriculumRecord c{
        session_id,         static_cast<int>(stmt.column_int(1)), stmt.column_text(2), stmt.column_text(3), {},
        stmt.column_text(4)};
    drills.bind(1, stmt.column_int(0));
    while (drills.step()) {
      c.drills.push_back({static_cast<int>(drills.column_int(0)), drills.column_text(1), drills.column_text(2)});
    }
    out.push_back(std::move(c));
  }
  return out;
}

template <typename Db>
std::vector<SessionSummary> query_study_sessions(Db& db, std::string_view study) {
  std::vector<SessionSummary> out;
  for (auto& row : query_session_summaries(db, "WHERE s.study_id = (SELECT id FROM studies WHERE name = ?1)", study))
    out.push_back(std::move(row.summary));
  return out;
}

// The record SQL runs on both stores (pg_handle.hpp has the same shape as sqlite_handle.hpp).
template std::optional<SessionRow> query_session(SqliteDb& db, std::int64_t session_id);
template std::vector<SessionRow> query_unfinished_sessions(SqliteDb& db, std::string_view learner,
                                                           std::string_view task);
template int query_session_count(SqliteDb& db, std::string_view learner, std::string_view task);
template int query_trial_count(SqliteDb& db, std::int64_t session_id);
template int query_last_seq(SqliteDb& db, std::int64_t session_id);
template std::vector<LearnerOverview> query_learners(SqliteDb& db);
template std::vector<SessionSummary> query_study_sessions(SqliteDb& db, std::string_view study);
template std::vector<StoredTrial> query_trials(SqliteDb& db, std::int64_t session_id);
template std::vector<DiagnosisRecord> query_diagnoses(SqliteDb& db, std::int64_t session_id);
template std::vector<CurriculumRecord> query_curricula(SqliteDb& db, std::int64_t session_id);
template std::optional<SessionRow> query_session(PgDb& db, std::int64_t session_id);
template std::vector<SessionRow> query_unfinished_sessions(PgDb& db, std::string_view learner, std::string_view task);
template int query_session_count(PgDb& db, std::string_view learner, std::string_view task);
template int query_trial_count(PgDb& db, std::int64_t session_id);
template int query_last_seq(PgDb& db, std::int64_t session_id);
template std::vector<LearnerOverview> query_learners(PgDb& db);
template std::vector<SessionSummary> query_study_sessions(PgDb& db, std::string_view study);
template std::vector<StoredTrial> query_trials(PgDb& db, std::int64_t session_id);
template std::vector<DiagnosisRecord> query_diagnoses(PgDb& db, std::int64_t session_id);
template std::vector<CurriculumRecord> query_curricula(PgDb& db, std::int64_t session_id);

}  // namespace sc::records
