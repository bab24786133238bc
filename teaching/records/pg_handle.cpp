#include "teaching/records/pg_handle.hpp"

#include <libpq-fe.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace sc::records {
namespace {

constexpr unsigned kInt8 = 20;
constexpr unsigned kText = 25;
constexpr unsigned kFloat8 = 701;

std::string first_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  const auto newline = text.find('\n');
  return newline == std::string::npos ? text : text.substr(0, newline);
}

}  // namespace

std::string to_postgres_parameters(std::string_view sql) {
  std::string out;
  out.reserve(sql.size());
  bool quoted = false;
  for (char c : sql) {
    if (c == '\'') quoted = !quoted;
    out += (c == '?' && !quoted) ? '$' : c;
  }
  return out;
}

std::string redact_password(std::string_view url) {
  const auto scheme = url.find("://");
  const auto at = url.find('@');
  if (scheme == std::string_view::npos || at == std::string_view::npos || at < scheme) return std::string(url);
  const auto colon = url.find(':', scheme + 3);
  if (colon == std::string_view::npos || colon > at) return std::string(url);
  return std::string(url.substr(0, colon)) + ":***" + std::string(url.substr(at));
}

PgStatement::PgStatement(PgDb& db, std::string_view sql) : db_(db), sql_(to_postgres_parameters(sql)) {}

PgStatement::~PgStatement() { PQclear(result_); }

void PgStatement::set(int index, std::optional<std::string> value, unsigned type) {
  const auto i = static_cast<std::size_t>(index - 1);
  if (values_.size() <= i) {
    values_.resize(i + 1);
    types_.resize(i + 1, kText);
  }
  values_[i] = std::move(value);
  types_[i] = type;
}

PgStatement& PgStatement::bind(int index, std::int64_t value) {
  set(index, std::to_string(value), kInt8);
  return *this;
}

PgStatement& PgStatement::bind(int index, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);  // every digit: the value reads back bit for bit
  set(index, std::string(text), kFloat8);
  return *this;
}

PgStatement& PgStatement::bind(int index, std::string_view text) {
  set(index, std::string(text), kText);
  return *this;
}

PgStatement& PgStatement::bind(int index, const std::optional<double>& value) {
  return value ? bind(index, *value) : (set(index, std::nullopt, kFloat8), *this);
}

PgStatement& PgStatement::bind(int index, const std::optional<std::int64_t>& value) {
  return value ? bind(index, *value) : (set(index, std::nullopt, kInt8), *this);
}

PgStatement& PgStatement::bind_null(int index) {
  set(index, std::nullopt, kText);
  return *this;
}

void PgStatement::execute() {
  std::vector<const char*> values;
  for (const auto& v : values_) values.push_back(v ? v->c_str() : nullptr);
  PGresult* result = PQexecParams(db_.raw(), sql_.c_str(), static_cast<int>(values.size()),
                                  reinterpret_cast<const Oid*>(types_.data()), values.data(), nullptr, nullptr, 0);
  db_.check(result, "");
  const char* tuples = PQcmdTuples(result);
  db_.set_changes(tuples != nullptr && *tuples != '\0' ? std::atoll(tuples) : 0);
  result_ = result;
  row_ = -1;
}

void PgStatement::reset() {
  PQclear(result_);
  result_ = nullptr;
  row_ = -1;
}

bool PgStatement::step() {
  if (result_ == nullptr) execute();
  if (++row_ < PQntuples(result_)) return true;
  reset();
  return false;
}

void PgStatement::run() {
  if (result_ == nullptr) execute();
  reset();
}

std::int64_t PgStatement::column_int(int index) const {
  const char* text = PQgetvalue(result_, row_, index);
  std::int64_t value = 0;
  std::from_chars(text, text + std::char_traits<char>::length(text), value);
  return value;
}

double PgStatement::column_double(int index) const { return std::strtod(PQgetvalue(result_, row_, index), nullptr); }

std::string PgStatement::column_text(int index) const {
  return std::string(PQgetvalue(result_, row_, index), static_cast<std::size_t>(PQgetlength(result_, row_, index)));
}

bool PgStatement::column_is_null(int index) const { return PQgetisnull(result_, row_, index) == 1; }

std::optional<double> PgStatement::column_optional_double(int index) const {
  if (column_is_null(index)) return std::nullopt;
  return column_double(index);
}

std::optional<std::int64_t> PgStatement::column_optional_int(int index) const {
  if (column_is_null(index)) return std::nullopt;
  return column_int(index);
}

PgDb::PgDb(const std::string& conninfo, int connect_timeout_s) {
  const std::string timeout = std::to_string(connect_timeout_s);
  const char* keys[] = {"dbname", "connect_timeout", "application_name", nullptr};
  const char* values[] = {conninfo.c_str(), timeout.c_str(), "skillcoach", nullptr};
  conn_ = PQconnectdbParams(keys, values, 1);  // expand_dbname: `dbname` may be a whole URL
  if (conn_ == nullptr || PQstatus(conn_) != CONNECTION_OK) {
    const std::string message = conn_ != nullptr ? first_line(PQerrorMessage(conn_)) : "out of memory";
    PQfinish(conn_);
    conn_ = nullptr;
    throw PgError("", true, "cannot connect: " + message);
  }
  PQsetNoticeProcessor(
      conn_, [](void*, const char*) {}, nullptr);  // "relation exists, skipping", ...
}

PgDb::~PgDb() { PQfinish(conn_); }

bool PgDb::connection_ok() const { return conn_ != nullptr && PQstatus(conn_) == CONNECTION_OK; }

void PgDb::check(PGresult* result, std::string_view what) {
  const auto status = PQresultStatus(result);
  if (status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK) return;
  const char* state = result != nullptr ? PQresultErrorField(result, PG_DIAG_SQLSTATE) : nullptr;
  std::string sqlstate = state != nullptr ? state : "";
  std::string message = first_line(result != nullptr ? PQresultErrorMessage(result) : PQerrorMessage(conn_));
  if (message.empty()) message = first_line(PQerrorMessage(conn_));
  PQclear(result);
  // Class 08 is a connection exception; a broken socket has no SQLSTATE but a bad connection status.
  const bool lost = !connection_ok() || sqlstate.rfind("08", 0) == 0 || sqlstate == "57P01";
  throw PgError(std::move(sqlstate), lost, what.empty() ? message : std::string(what) + ": " + message);
}

void PgDb::exec(std::string_view sql) {
  PGresult* result = PQexec(conn_, std::string(sql).c_str());
  check(result, "");  // frees a failed result
  PQclear(result);
}

std::int64_t PgDb::query_int(std::string_view sql) {
  auto stmt = prepare(sql);
  return stmt.step() ? stmt.column_int(0) : 0;
}

void PgDb::fail_conflict(const std::string& message) const { throw PgError("23505", false, message); }

PgTransaction::PgTransaction(PgDb& db) : db_(db) { db_.exec("BEGIN"); }

PgTransaction::~PgTransaction() {
  if (committed_ || !db_.connection_ok()) return;
  try {
    db_.exec("ROLLBACK");
  } catch (const PgError&) {  // the connection broke meanwhile: the server rolls back by itself
  }
}

void PgTransaction::commit() {
  db_.exec("COMMIT");
  committed_ = true;
}

}  // namespace sc::records
