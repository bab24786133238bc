#include "teaching/records/sqlite_handle.hpp"

#include <sqlite3.h>

namespace sc::records {

void check_sqlite(sqlite3* db, int code, std::string_view what) {
  if (code == SQLITE_OK || code == SQLITE_ROW || code == SQLITE_DONE) return;
  // sqlite3_errmsg describes the most recent failure on the connection; errstr describes the code alone.
  const int extended = db != nullptr ? sqlite3_extended_errcode(db) : code;
  const char* text = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(code);
  throw SqliteError((extended & 0xff) == (code & 0xff) ? extended : code, std::string(what) + ": " + text);
}

SqliteStatement::SqliteStatement(sqlite3* db, std::string_view sql) : db_(db) {
  check_sqlite(db_, sqlite3_prepare_v2(db_, sql.data(), static_cast<int>(sql.size()), &stmt_, nullptr), "prepare");
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(stmt_); }

SqliteStatement& SqliteStatement::bind(int index, std::int64_t value) {
  check_sqlite(db_, sqlite3_bind_int64(stmt_, index, value), "bind");
  return *this;
}

SqliteStatement& SqliteStatement::bind(int index, double value) {
  check_sqlite(db_, sqlite3_bind_double(stmt_, index, value), "bind");
  return *this;
}

SqliteStatement& SqliteStatement::bind(int index, std::string_view text) {
  // SQLITE_TRANSIENT: SQLite copies the text, so callers may pass temporaries.
  // An empty string_view may have a null data(), which SQLite would bind as NULL instead of ''.
  const char* data = text.data() != nullptr ? text.data() : "";
  check_sqlite(db_, sqlite3_bind_text64(stmt_, index, data, text.size(), SQLITE_TRANSIENT, SQLITE_UTF8), "bind");
  return *this;
}

SqliteStatement& SqliteStatement::bind(int index, const std::optional<double>& value) {
  return value ? bind(index, *value) : bind_null(index);
}

SqliteStatement& SqliteStatement::bind(int index, const std::optional<std::int64_t>& value) {
  return value ? bind(index, *value) : bind_null(index);
}

SqliteStatement& SqliteStatement::bind_null(int index) {
  check_sqlite(db_, sqlite3_bind_null(stmt_, index), "bind");
  return *this;
}

bool SqliteStatement::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  // Reset when done (or failed) so the statement can be bound and run again.
  sqlite3_reset(stmt_);
  if (rc == SQLITE_DONE) return false;
  check_sqlite(db_, rc, "step");
  return false;
}

void SqliteStatement::run() {
  while (step()) {}
}

std::int64_t SqliteStatement::column_int(int index) const { return sqlite3_column_int64(stmt_, index); }

double SqliteStatement::column_double(int index) const { return sqlite3_column_double(stmt_, index); }

std::string SqliteStatement::column_text(int index) const {
  const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, index));
  if (text == nullptr) return {};
  return std::string(text, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, index)));
}

bool SqliteStatement::column_is_null(int index) const { return sqlite3_column_type(stmt_, index) == SQLITE_NULL; }

std::optional<double> SqliteStatement::column_optional_double(int index) const {
  if (column_is_null(index)) return std::nullopt;
  return column_double(index);
}

std::optional<std::int64_t> SqliteStatement::column_optional_int(int index) const {
  if (column_is_null(index)) return std::nullopt;
  return column_int(index);
}

SqliteDb::SqliteDb(const std::filesystem::path& file, Mode mode, std::string_view uri_query) {
  int flags = SQLITE_OPEN_EXRESCODE | SQLITE_OPEN_NOMUTEX;
  flags |= mode == Mode::ReadOnly ? SQLITE_OPEN_READONLY : (SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
  std::string name = file.string();
  if (!uri_query.empty()) {
    // Percent-encode the characters that have a meaning in a URI path.
    std::string uri = "file:";
    for (char c : name) {
      if (c == '%' || c == '?' || c == '#') {
        static constexpr char kHex[] = "0123456789ABCDEF";
        uri += '%';
        uri += kHex[(static_cast<unsigned char>(c) >> 4) & 0xf];
        uri += kHex[static_cast<unsigned char>(c) & 0xf];
      } else {
        uri += c;
      }
    }
    name = uri + "?" + std::string(uri_query);
    flags |= SQLITE_OPEN_URI;
  }
  const int rc = sqlite3_open_v2(name.c_str(), &db_, flags, nullptr);
  if (rc != SQLITE_OK) {
    std::string message = db_ != nullptr ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    const int code = db_ != nullptr ? sqlite3_extended_errcode(db_) : rc;
    sqlite3_close_v2(db_);
    db_ = nullptr;
    throw SqliteError(code, "open: " + message);
  }
}

SqliteDb::~SqliteDb() { sqlite3_close_v2(db_); }

void SqliteDb::exec(std::string_view sql) {
  char* error = nullptr;
  const std::string text(sql);
  const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error);
  if (rc != SQLITE_OK) {
    std::string message = error != nullptr ? error : sqlite3_errstr(rc);
    sqlite3_free(error);
    throw SqliteError(sqlite3_extended_errcode(db_), message);
  }
}

std::int64_t SqliteDb::query_int(std::string_view sql) {
  auto stmt = prepare(sql);
  return stmt.step() ? stmt.column_int(0) : 0;
}

std::string SqliteDb::query_text(std::string_view sql) {
  auto stmt = prepare(sql);
  return stmt.step() ? stmt.column_text(0) : std::string();
}

bool SqliteDb::is_read_only() const { return sqlite3_db_readonly(db_, "main") == 1; }

std::int64_t SqliteDb::last_insert_id() const { return sqlite3_last_insert_rowid(db_); }

std::int64_t SqliteDb::changes() const { return sqlite3_changes64(db_); }

void SqliteDb::fail_conflict(const std::string& message) const { throw SqliteError(SQLITE_CONSTRAINT_UNIQUE, message); }

void SqliteDb::set_busy_timeout(int milliseconds) { sqlite3_busy_timeout(db_, milliseconds); }

SqliteTransaction::SqliteTransaction(SqliteDb& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }

SqliteTransaction::~SqliteTransaction() {
  if (committed_) return;
  try {
    db_.exec("ROLLBACK");
  } catch (const SqliteError&) {  // SQLite already rolled back by itself (e.g. after SQLITE_FULL)
  }
}

void SqliteTransaction::commit() {
  db_.exec("COMMIT");
  committed_ = true;
}

// Plain words for the storage faults a learner may meet; anything else keeps SQLite's own text.
std::string describe_storage_error(const SqliteError& e) {
  switch (e.primary_code()) {
    case SQLITE_FULL:
      return "the disk or the database is full";
    case SQLITE_READONLY:
      return "the database is read-only";
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return "the database is locked by another program";
    case SQLITE_IOERR:
      return std::string("disk I/O error (") + e.what() + ")";
    case SQLITE_CANTOPEN:
    case SQLITE_PERM:
      return "the database file cannot be opened for writing";
    default:
      return e.what();
  }
}

// Faults that go away by themselves or when the user frees space / fixes permissions; anything else
// (e.g. a missing table) needs the database repaired, so promising a retry would mislead.
bool is_storage_fault(const SqliteError& e) {
  switch (e.primary_code()) {
    case SQLITE_FULL:
    case SQLITE_READONLY:
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
    case SQLITE_IOERR:
    case SQLITE_CANTOPEN:
    case SQLITE_PERM:
      return true;
    default:
      return false;
  }
}

}  // namespace sc::records
