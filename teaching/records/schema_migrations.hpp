#pragma once
// Versioned schema of the learner database. The database's `PRAGMA user_version` is the number of the
// last migration applied; `PRAGMA application_id` marks the file as SkillCoach's. Opening a database
// applies the missing migrations in one transaction (all or nothing). Never edit a released migration:
// append a new one (see docs/database.md).
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include "teaching/records/sqlite_handle.hpp"

namespace sc::records {

// "SkCo": identifies a SkillCoach database among other SQLite files.
inline constexpr std::int32_t kSkillCoachApplicationId = 0x536B436F;

struct Migration {
  int version;                   // 1, 2, ... consecutive
  std::string_view description;  // one line, for docs and errors
  std::string_view sql;          // statements run inside the migration transaction
};

// The migrations of this build, in order; the last one's version is the current schema version.
std::span<const Migration> schema_migrations();
int current_schema_version();

// Brings `db` from its user_version up to the last of `migrations` inside one IMMEDIATE transaction and
// stamps the application id. The caller has checked the file is ours (or empty) and not newer.
// `file` names the database in errors. Throws SqliteError if SQLite fails (nothing is applied then).
void migrate(SqliteDb& db, std::span<const Migration> migrations, std::string_view file);
// A copy of `source` in memory (SQLite's backup API), brought up to the last of `migrations`: how read-only
// readers see an older database without changing its file. Throws SqliteError if SQLite fails.
std::unique_ptr<SqliteDb> migrated_in_memory(SqliteDb& source, std::span<const Migration> migrations,
                                             std::string_view file);

}  // namespace sc::records
