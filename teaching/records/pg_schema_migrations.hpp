#pragma once
// The learner schema on PostgreSQL: the same versions as schema_migrations.hpp (version N here holds what
// version N holds in a SQLite file), in PostgreSQL's dialect. The version lives in the table
// skillcoach_schema (SQLite's PRAGMA user_version has no PostgreSQL equivalent). Never edit a released
// migration: append a new one to both lists (tests/records/pg_schema_migrations_test.cpp checks they agree).
#include <span>
#include <string_view>

#include "teaching/records/pg_handle.hpp"
#include "teaching/records/schema_migrations.hpp"

namespace sc::records {

std::span<const Migration> pg_schema_migrations();

// The schema version of the connected database: 0 for an empty one. Throws sc::InputError naming `where`
// when the database holds tables that are not SkillCoach's.
int pg_schema_version(PgDb& db, std::string_view where);
// Brings the database up to the last migration in one transaction, under an advisory lock so that desktops
// starting together migrate once. Throws sc::InputError for a newer schema, PgError when the server fails.
void migrate_postgres(PgDb& db, std::string_view where);

}  // namespace sc::records
