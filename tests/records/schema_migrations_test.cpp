// The migration mechanism, exercised with a fixture list: a v1 database made here is upgraded to v2,
// data survives, and a failing migration leaves the database exactly as it was.
#include "teaching/records/schema_migrations.hpp"

#include <array>

#include <gtest/gtest.h>

#include "tests/records/records_test_support.hpp"

namespace sc::records {
namespace {

constexpr Migration kV1{1, "notes table", "CREATE TABLE notes(id INTEGER PRIMARY KEY, text TEXT NOT NULL);"};
constexpr Migration kV2{2, "note authors",
                        "ALTER TABLE notes ADD COLUMN author TEXT NOT NULL DEFAULT 'unknown';"
                        "CREATE INDEX notes_by_author ON notes(author);"};
constexpr Migration kV3Broken{3, "broken", "ALTER TABLE notes ADD COLUMN x; CREATE TABLE notes(id);"};

TEST(SchemaMigrations, UpgradesAVersion1DatabaseAndKeepsItsData) {
  const auto file = test::fresh_dir("migrate") / "fixture.db";
  {
    SqliteDb db(file, SqliteDb::Mode::ReadWriteCreate);
    migrate(db, std::array{kV1}, file.string());
    EXPECT_EQ(db.query_int("PRAGMA user_version"), 1);
    db.exec("INSERT INTO notes(text) VALUES('kept')");
  }
  SqliteDb db(file, SqliteDb::Mode::ReadWriteCreate);
  migrate(db, std::array{kV1, kV2}, file.string());
  EXPECT_EQ(db.query_int("PRAGMA user_version"), 2);
  EXPECT_EQ(db.query_int("PRAGMA application_id"), kSkillCoachApplicationId);
  EXPECT_EQ(db.query_text("SELECT text || '/' || author FROM notes"), "kept/unknown");
  // Migrating an up-to-date database changes nothing.
  migrate(db, std::array{kV1, kV2}, file.string());
  EXPECT_EQ(db.query_int("SELECT count(*) FROM notes"), 1);
}

TEST(SchemaMigrations, AFailingMigrationLeavesTheDatabaseAsItWas) {
  const auto file = test::fresh_dir("migrate-fail") / "fixture.db";
  SqliteDb db(file, SqliteDb::Mode::ReadWriteCreate);
  migrate(db, std::array{kV1}, file.string());
  db.exec("INSERT INTO notes(text) VALUES('kept')");
  // v2 would succeed on its own, but v3 fails: neither is applied.
  try {
    migrate(db, std::array{kV1, kV2, kV3Broken}, file.string());
    FAIL() << "the broken migration did not fail";
  } catch (const SqliteError& e) {
    EXPECT_NE(std::string(e.what()).find("migration to schema version 3 (broken) failed"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(db.query_int("PRAGMA user_version"), 1);
  EXPECT_EQ(db.query_int("SELECT count(*) FROM pragma_table_info('notes') WHERE name = 'author'"), 0);
  EXPECT_EQ(db.query_text("SELECT text FROM notes"), "kept");
}

TEST(SchemaMigrations, RefusesToDowngrade) {
  const auto file = test::fresh_dir("migrate-newer") / "fixture.db";
  SqliteDb db(file, SqliteDb::Mode::ReadWriteCreate);
  migrate(db, std::array{kV1, kV2}, file.string());
  EXPECT_EQ(test::error_of([&] { migrate(db, std::array{kV1}, file.string()); }),
            file.string() + ": schema version 2 is newer than this build (1); it was not changed");
  EXPECT_EQ(db.query_int("PRAGMA user_version"), 2);
}

TEST(SchemaMigrations, AnInMemoryCopyIsMigratedAndTheFileIsNot) {
  const auto file = test::fresh_dir("migrate-copy") / "fixture.db";
  {
    SqliteDb db(file, SqliteDb::Mode::ReadWriteCreate);
    migrate(db, std::array{kV1}, file.string());
    db.exec("INSERT INTO notes(text) VALUES('kept')");
  }
  const std::string before = test::file_bytes(file);
  SqliteDb source(file, SqliteDb::Mode::ReadOnly);
  const auto copy = migrated_in_memory(source, std::array{kV1, kV2}, file.string());
  EXPECT_EQ(copy->query_int("PRAGMA user_version"), 2);
  EXPECT_EQ(copy->query_text("SELECT text || '/' || author FROM notes"), "kept/unknown");
  EXPECT_EQ(source.query_int("PRAGMA user_version"), 1);
  EXPECT_EQ(test::file_bytes(file), before);
}

TEST(SchemaMigrations, ListIsConsecutiveFromOne) {
  int expected = 1;
  for (const auto& migration : schema_migrations()) EXPECT_EQ(migration.version, expected++);
  EXPECT_EQ(current_schema_version(), expected - 1);
}

}  // namespace
}  // namespace sc::records
