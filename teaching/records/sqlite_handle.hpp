#pragma once
// A thin RAII layer over the SQLite C API: one connection (SqliteDb) and prepared statements
// (SqliteStatement). Failures throw SqliteError carrying the extended result code, so the learner store
// can tell a storage fault (disk full, read-only, locked) from bad input and keep the learner's work.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

struct sqlite3;
struct sqlite3_stmt;

namespace sc::records {

class SqliteError : public std::runtime_error {
 public:
  SqliteError(int code, const std::string& message) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }                 // extended result code (e.g. SQLITE_READONLY_DBMOVED)
  int primary_code() const { return code_ & 0xff; }  // SQLITE_FULL, SQLITE_BUSY, ...

 private:
  int code_;
};

class SqliteStatement {
 public:
  SqliteStatement(sqlite3* db, std::string_view sql);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  // Parameters are 1-based, as in SQLite.
  SqliteStatement& bind(int index, std::int64_t value);
  SqliteStatement& bind(int index, double value);
  SqliteStatement& bind(int index, std::string_view text);
  SqliteStatement& bind(int index, const std::optional<double>& value);
  SqliteStatement& bind(int index, const std::optional<std::int64_t>& value);
  SqliteStatement& bind_null(int index);

  // Returns true while a row is available; false when done (the statement is then reset, ready to be
  // bound and run again).
  bool step();
  // Runs a statement that returns no rows (or ignores them).
  void run();

  std::int64_t column_int(int index) const;
  double column_double(int index) const;
  std::string column_text(int index) const;
  bool column_is_null(int index) const;
  std::optional<double> column_optional_double(int index) const;
  std::optional<std::int64_t> column_optional_int(int index) const;

 private:
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

class SqliteDb {
 public:
  enum class Mode { ReadOnly, ReadWriteCreate };
  // A non-empty `uri_query` (e.g. "immutable=1") opens through a file: URI with that query.
  SqliteDb(const std::filesystem::path& file, Mode mode, std::string_view uri_query = {});
  ~SqliteDb();
  SqliteDb(const SqliteDb&) = delete;
  SqliteDb& operator=(const SqliteDb&) = delete;

  void exec(std::string_view sql);
  SqliteStatement prepare(std::string_view sql) { return SqliteStatement(db_, sql); }
  // Result of a pragma or a one-value query.
  std::int64_t query_int(std::string_view sql);
  std::string query_text(std::string_view sql);

  bool is_read_only() const;
  std::int64_t last_insert_id() const;
  std::int64_t changes() const;  // rows changed by the last statement
  // The unique-key conflict of a replayed write: throws SqliteError(SQLITE_CONSTRAINT_UNIQUE).
  [[noreturn]] void fail_conflict(const std::string& message) const;
  void set_busy_timeout(int milliseconds);
  sqlite3* raw() { return db_; }

 private:
  sqlite3* db_ = nullptr;
};

// BEGIN IMMEDIATE (takes the write lock at once, so a busy database fails here and not half-way);
// rolls back unless committed, so a failing write leaves the database as it was.
class SqliteTransaction {
 public:
  explicit SqliteTransaction(SqliteDb& db);
  ~SqliteTransaction();
  SqliteTransaction(const SqliteTransaction&) = delete;
  SqliteTransaction& operator=(const SqliteTransaction&) = delete;
  void commit();

 private:
  SqliteDb& db_;
  bool committed_ = false;
};

// Throws SqliteError for `code` unless it is SQLITE_OK/ROW/DONE; `db` supplies the message (may be null).
void check_sqlite(sqlite3* db, int code, std::string_view what);

// Plain words for the storage faults a learner may meet (disk full, read-only, locked, ...); anything
// else keeps SQLite's own text.
std::string describe_storage_error(const SqliteError& e);
// Faults that pass by themselves or once the user frees space or fixes permissions; anything else (e.g. a
// missing table) needs the database repaired, so a retry must not be promised.
bool is_storage_fault(const SqliteError& e);

}  // namespace sc::records
