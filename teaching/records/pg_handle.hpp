#pragma once
// A thin RAII layer over libpq with the same shape as sqlite_handle.hpp (PgDb ~ SqliteDb, PgStatement ~
// SqliteStatement), so the record SQL (record_writes, record_queries, record_studies) is written once and
// runs on both stores. Statements are written with SQLite's "?N" parameters; PgDb turns them into "$N".
// Values travel as text with explicit types (int8, float8, text), so a double keeps every digit.
// Failures throw PgError carrying the SQLSTATE and whether the connection itself was lost, so the
// PostgreSQL store can tell an unreachable server (queue the record) from a refused one.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct pg_conn;
struct pg_result;

namespace sc::records {

class PgError : public std::runtime_error {
 public:
  PgError(std::string sqlstate, bool connection_lost, const std::string& message)
      : std::runtime_error(message), sqlstate_(std::move(sqlstate)), connection_lost_(connection_lost) {}
  const std::string& sqlstate() const { return sqlstate_; }  // "23505", ...; empty when there is none
  bool connection_lost() const { return connection_lost_; }  // the server cannot be reached (any more)

 private:
  std::string sqlstate_;
  bool connection_lost_;
};

class PgDb;

class PgStatement {
 public:
  PgStatement(PgDb& db, std::string_view sql);
  ~PgStatement();
  PgStatement(const PgStatement&) = delete;
  PgStatement& operator=(const PgStatement&) = delete;

  PgStatement& bind(int index, std::int64_t value);
  PgStatement& bind(int index, double value);
  PgStatement& bind(int index, std::string_view text);
  PgStatement& bind(int index, const std::optional<double>& value);
  PgStatement& bind(int index, const std::optional<std::int64_t>& value);
  PgStatement& bind_null(int index);

  // As SqliteStatement: true while a row is available; false when done (then ready to be bound again).
  bool step();
  void run();

  std::int64_t column_int(int index) const;
  double column_double(int index) const;
  std::string column_text(int index) const;
  bool column_is_null(int index) const;
  std::optional<double> column_optional_double(int index) const;
  std::optional<std::int64_t> column_optional_int(int index) const;

 private:
  void set(int index, std::optional<std::string> value, unsigned type);
  void execute();
  void reset();

  PgDb& db_;
  std::string sql_;
  std::vector<std::optional<std::string>> values_;
  std::vector<unsigned> types_;
  pg_result* result_ = nullptr;
  int row_ = -1;
};

class PgDb {
 public:
  // `conninfo`: a postgresql:// URL or key=value string. Throws PgError (connection_lost) when the server
  // cannot be reached; waits at most `connect_timeout_s` seconds.
  PgDb(const std::string& conninfo, int connect_timeout_s);
  ~PgDb();
  PgDb(const PgDb&) = delete;
  PgDb& operator=(const PgDb&) = delete;

  void exec(std::string_view sql);
  PgStatement prepare(std::string_view sql) { return PgStatement(*this, sql); }
  std::int64_t query_int(std::string_view sql);
  // Rows changed by the last statement run (as sqlite3_changes).
  std::int64_t changes() const { return changes_; }
  bool is_read_only() const { return false; }
  // The unique-key conflict of a replayed write: throws PgError with SQLSTATE 23505.
  [[noreturn]] void fail_conflict(const std::string& message) const;
  bool connection_ok() const;
  pg_conn* raw() { return conn_; }

  // Throws PgError for a failed result (and frees it); a successful one stays the caller's to free.
  // `what` prefixes the message.
  void check(pg_result* result, std::string_view what);
  void set_changes(std::int64_t n) { changes_ = n; }

 private:
  pg_conn* conn_ = nullptr;
  std::int64_t changes_ = 0;
};

// BEGIN ... COMMIT; rolls back unless committed (nothing to roll back once the connection is gone).
class PgTransaction {
 public:
  explicit PgTransaction(PgDb& db);
  ~PgTransaction();
  PgTransaction(const PgTransaction&) = delete;
  PgTransaction& operator=(const PgTransaction&) = delete;
  void commit();

 private:
  PgDb& db_;
  bool committed_ = false;
};

// SQLite's "?N" parameters as PostgreSQL's "$N" (outside quoted text).
std::string to_postgres_parameters(std::string_view sql);
// The URL without its password, for messages and file names.
std::string redact_password(std::string_view url);

}  // namespace sc::records
