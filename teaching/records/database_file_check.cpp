#include "teaching/records/database_file_check.hpp"

#include <array>
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>

#include <sqlite3.h>
#include <unistd.h>

#include "engine/core/error.hpp"
#include "teaching/records/schema_migrations.hpp"
#include "teaching/records/sqlite_handle.hpp"

namespace sc::records {
namespace {

constexpr std::size_t kHeaderSize = 100;  // https://www.sqlite.org/fileformat.html#the_database_header

std::uint32_t big_endian_u32(const std::array<unsigned char, kHeaderSize>& h, std::size_t at) {
  return (std::uint32_t{h[at]} << 24) | (std::uint32_t{h[at + 1]} << 16) | (std::uint32_t{h[at + 2]} << 8) |
         std::uint32_t{h[at + 3]};
}

std::string hex32(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", value);
  return text;
}

bool wal_has_content(const std::filesystem::path& file) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(file.string() + "-wal", ec);
  return !ec && size > 0;
}

// Header checks that catch garbage and truncation before SQLite sees the file.
void check_header(const std::filesystem::path& file, std::uintmax_t size) {
  const std::string where = file.string();
  if (size < kHeaderSize)
    throw InputError(
        where, "not a SQLite database or truncated (only " + std::to_string(size) + " bytes); it was not changed");
  std::array<unsigned char, kHeaderSize> header{};
  std::ifstream in(file, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(header.data()), kHeaderSize)) throw InputError(where, "cannot be read");
  static constexpr char kMagic[] = "SQLite format 3";  // 16 bytes with its NUL
  if (!std::equal(kMagic, kMagic + 16, header.begin()))
    throw InputError(where, "not a SQLite database (unrecognised header); it was not changed");
  std::uint32_t page_size = (std::uint32_t{header[16]} << 8) | header[17];
  if (page_size == 1) page_size = 65536;
  if (page_size < 512 || page_size > 65536 || (page_size & (page_size - 1)) != 0)
    throw InputError(where, "damaged SQLite header (page size " + std::to_string(page_size) + "); it was not changed");
  if (size % page_size != 0)
    throw InputError(where, "truncated or damaged: " + std::to_string(size) + " bytes is not a whole number of " +
                                std::to_string(page_size) + "-byte pages; it was not changed");
  // The in-header page count is valid when the "version-valid-for" number matches the change counter.
  // With a non-empty write-ahead log it may count pages that only the log holds yet: a checkpoint that
  // failed on a full disk writes page 1 and then cannot grow the file. quick_check judges that case.
  const auto pages = big_endian_u32(header, 28);
  if (pages != 0 && !wal_has_content(file) && big_endian_u32(header, 92) == big_endian_u32(header, 24) &&
      std::uintmax_t{pages} * page_size > size) {
    throw InputError(where, "truncated: the header counts " + std::to_string(pages) + " pages but the file holds " +
                                std::to_string(size / page_size) + "; it was not changed");
  }
}

// A read-only connection; falls back to `immutable=1` when SQLite cannot create the WAL index.
std::unique_ptr<SqliteDb> open_for_inspection(const std::filesystem::path& file) {
  if (read_immutably(file)) return std::make_unique<SqliteDb>(file, SqliteDb::Mode::ReadOnly, "immutable=1");
  try {
    auto db = std::make_unique<SqliteDb>(file, SqliteDb::Mode::ReadOnly);
    db->query_int("PRAGMA schema_version");  // forces the first read
    return db;
  } catch (const SqliteError& e) {
    if (e.primary_code() != SQLITE_READONLY && e.primary_code() != SQLITE_CANTOPEN) throw;
  }
  return std::make_unique<SqliteDb>(file, SqliteDb::Mode::ReadOnly, "immutable=1");
}

std::string first_table_name(SqliteDb& db) {
  return db.query_text("SELECT name FROM sqlite_schema WHERE type = 'table' ORDER BY name LIMIT 1");
}

}  // namespace

bool read_immutably(const std::filesystem::path& file) {
  const auto dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  if (::access(file.c_str(), W_OK) == 0 && ::access(dir.c_str(), W_OK) == 0) return false;
  std::error_code ec;
  const auto wal_size = std::filesystem::file_size(file.string() + "-wal", ec);
  return ec || wal_size == 0;
}

DatabaseFileState check_database_file(const std::filesystem::path& file, int newest_version) {
  const std::string where = file.string();
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) {
    // Non-throwing checks: a data directory we may not search (EACCES) is a one-line problem, not a crash.
    if (ec == std::errc::no_such_file_or_directory) return {true, 0};
    throw InputError(where, "cannot be read: " + ec.message());
  }
  if (size == 0) return {true, 0};
  check_header(file, size);

  try {
    auto db = open_for_inspection(file);
    const std::string verdict = db->query_text("PRAGMA quick_check(1)");
    if (verdict != "ok") throw InputError(where, "damaged database (" + verdict + "); it was not changed");
    const auto application_id = static_cast<std::uint32_t>(db->query_int("PRAGMA application_id"));
    const auto version = static_cast<int>(db->query_int("PRAGMA user_version"));
    const auto tables = db->query_int("SELECT count(*) FROM sqlite_schema WHERE type = 'table'");
    if (application_id == 0 && version == 0 && tables == 0) return {true, 0};
    if (application_id != static_cast<std::uint32_t>(kSkillCoachApplicationId)) {
      std::string detail = application_id != 0
                               ? "application id " + hex32(application_id)
                               : std::to_string(tables) + " tables, e.g. '" + first_table_name(*db) + "'";
      throw InputError(where, "not a SkillCoach database (" + detail + "); it was not changed");
    }
    if (version > newest_version) {
      throw InputError(where, "written by a newer SkillCoach (schema version " + std::to_string(version) +
                                  ", this build understands up to " + std::to_string(newest_version) +
                                  "); it was not changed");
    }
    return {false, version};
  } catch (const SqliteError& e) {
    const bool damaged = e.primary_code() == SQLITE_CORRUPT || e.primary_code() == SQLITE_NOTADB;
    throw InputError(
        where, std::string(damaged ? "damaged database (" : "cannot be read (") + e.what() + "); it was not changed");
  }
}

}  // namespace sc::records
