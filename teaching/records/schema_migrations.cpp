#include "teaching/records/schema_migrations.hpp"

#include <sqlite3.h>

#include <array>
#include <string>

#include "engine/core/error.hpp"

namespace sc::records {
namespace {

// Version 1: the first schema. Natural keys (session + seq, session + round, curriculum + index)
// are UNIQUE so that replaying a pending write after a crash can never duplicate a record.
constexpr std::string_view kSchemaV1 = R"sql(
CREATE TABLE learners(
  id      INTEGER PRIMARY KEY,
  name    TEXT NOT NULL UNIQUE CHECK(length(trim(name)) > 0),
  created TEXT NOT NULL
);
CREATE TABLE sessions(
  id         INTEGER PRIMARY KEY,
  learner_id INTEGER NOT NULL REFERENCES learners(id) ON DELETE CASCADE,
  task       TEXT NOT NULL CHECK(length(task) > 0),
  condition  TEXT NOT NULL CHECK(length(condition) > 0),
  seed       INTEGER NOT NULL,
  settings   TEXT NOT NULL DEFAULT '{}' CHECK(json_valid(settings)),
  started    TEXT NOT NULL,
  finished   TEXT,
  round      INTEGER NOT NULL DEFAULT 1 CHECK(round >= 1),
  phase      TEXT NOT NULL DEFAULT 'pretest'
             CHECK(phase IN ('pretest', 'diagnosis', 'drills', 'evaluation', 'summary')),
  item_index INTEGER NOT NULL DEFAULT 0 CHECK(item_index >= 0)
);
CREATE INDEX sessions_by_learner ON sessions(learner_id, started);
CREATE TABLE trials(
  id          INTEGER PRIMARY KEY,
  session_id  INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
  seq         INTEGER NOT NULL CHECK(seq >= 1),
  kind        TEXT NOT NULL CHECK(kind IN ('pretest', 'demo', 'practice', 'eval')),
  round       INTEGER NOT NULL CHECK(round >= 1),
  drill_index INTEGER,
  task        TEXT NOT NULL,
  scenario    TEXT NOT NULL CHECK(json_valid(scenario)),
  trajectory  TEXT NOT NULL CHECK(json_valid(trajectory)),
  score       REAL,
  device      TEXT NOT NULL,
  started     TEXT NOT NULL,
  finished    TEXT NOT NULL,
  UNIQUE(session_id, seq)
);
CREATE TABLE diagnoses(
  id         INTEGER PRIMARY KEY,
  session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
  round      INTEGER NOT NULL CHECK(round >= 1),
  expertise  TEXT NOT NULL CHECK(json_valid(expertise)),
  targets    TEXT NOT NULL CHECK(json_valid(targets)),
  extractor  TEXT NOT NULL,
  model_id   TEXT NOT NULL DEFAULT '',
  created    TEXT NOT NULL,
  UNIQUE(session_id, round)
);
CREATE TABLE curricula(
  id         INTEGER PRIMARY KEY,
  session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
  round      INTEGER NOT NULL CHECK(round >= 1),
  condition  TEXT NOT NULL,
  items      TEXT NOT NULL CHECK(json_valid(items)),
  created    TEXT NOT NULL,
  UNIQUE(session_id, round)
);
CREATE TABLE drills(
  id            INTEGER PRIMARY KEY,
  curriculum_id INTEGER NOT NULL REFERENCES curricula(id) ON DELETE CASCADE,
  idx           INTEGER NOT NULL CHECK(idx >= 0),
  skills        TEXT NOT NULL CHECK(json_valid(skills)),
  content       TEXT NOT NULL CHECK(json_valid(content)),
  UNIQUE(curriculum_id, idx)
);
)sql";

// Version 2: studies. A study's participants and their assigned conditions; a session names its study.
// UNIQUE(study, seq) makes two enrolments racing for one place impossible (the second one fails).
constexpr std::string_view kSchemaV2 = R"sql(
CREATE TABLE studies(
  id                   INTEGER PRIMARY KEY,
  name                 TEXT NOT NULL UNIQUE CHECK(length(trim(name)) > 0),
  task                 TEXT NOT NULL CHECK(length(task) > 0),
  conditions           TEXT NOT NULL CHECK(json_valid(conditions) AND json_array_length(conditions) >= 2),
  target_per_condition INTEGER NOT NULL CHECK(target_per_condition >= 1),
  seed                 INTEGER NOT NULL,
  created              TEXT NOT NULL
);
CREATE TABLE study_participants(
  id         INTEGER PRIMARY KEY,
  study_id   INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,
  learner_id INTEGER NOT NULL REFERENCES learners(id) ON DELETE CASCADE,
  seq        INTEGER NOT NULL CHECK(seq >= 1),
  condition  TEXT NOT NULL CHECK(length(condition) > 0),
  enrolled   TEXT NOT NULL,
  UNIQUE(study_id, learner_id),
  UNIQUE(study_id, seq)
);
ALTER TABLE sessions ADD COLUMN study_id INTEGER REFERENCES studies(id) ON DELETE SET NULL;
CREATE INDEX sessions_by_study ON sessions(study_id) WHERE study_id IS NOT NULL;
)sql";

constexpr std::array<Migration, 2> kMigrations{{
    {1, "learners, sessions, trials, diagnoses, curricula and drills", kSchemaV1},
    {2, "studies, their participants, and the study of a session", kSchemaV2},
}};

}  // namespace

std::span<const Migration> schema_migrations() { return kMigrations; }

int current_schema_version() { return kMigrations.back().version; }

void migrate(SqliteDb& db, std::span<const Migration> migrations, std::string_view file) {
  const int target = migrations.empty() ? 0 : migrations.back().version;
  // Cheap check outside a transaction: an up-to-date database is not locked for writing on open.
  if (db.query_int("PRAGMA user_version") == target) return;
  SqliteTransaction transaction(db);
  // Re-read inside the write lock: another process may have migrated meanwhile.
  const auto version = db.query_int("PRAGMA user_version");
  if (version > target) {
    throw InputError(file, "schema version " + std::to_string(version) + " is newer than this build (" +
                               std::to_string(target) + "); it was not changed");
  }
  for (const auto& migration : migrations) {
    if (migration.version <= version) continue;
    try {
      db.exec(migration.sql);
    } catch (const SqliteError& e) {
      throw SqliteError(e.code(), "migration to schema version " + std::to_string(migration.version) + " (" +
                                      std::string(migration.description) + ") failed: " + e.what());
    }
  }
  db.exec("PRAGMA application_id = " + std::to_string(kSkillCoachApplicationId));
  db.exec("PRAGMA user_version = " + std::to_string(target));
  transaction.commit();
}

std::unique_ptr<SqliteDb> migrated_in_memory(SqliteDb& source, std::span<const Migration> migrations,
                                             std::string_view file) {
  auto copy = std::make_unique<SqliteDb>(":memory:", SqliteDb::Mode::ReadWriteCreate);
  sqlite3_backup* backup = sqlite3_backup_init(copy->raw(), "main", source.raw(), "main");
  if (backup == nullptr) throw SqliteError(sqlite3_extended_errcode(copy->raw()), "copy for reading failed");
  const int stepped = sqlite3_backup_step(backup, -1);
  const int finished = sqlite3_backup_finish(backup);
  if (stepped != SQLITE_DONE || finished != SQLITE_OK)
    throw SqliteError(stepped != SQLITE_DONE ? stepped : finished, "copy for reading failed");
  copy->exec("PRAGMA foreign_keys = ON");
  migrate(*copy, migrations, file);
  return copy;
}

}  // namespace sc::records
