#pragma once
// The store a parametrized record-store test runs on: a fresh SQLite data directory, or a fresh database
// on the throwaway PostgreSQL server of the ctest fixture pg_server (its socket directory is
// $SKILLCOACH_TEST_PG_HOST). A missing server fails the test; SKILLCOACH_NO_POSTGRES=1 skips it.
#include <cstdlib>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "teaching/records/open_record_store.hpp"
#include "teaching/records/pg_handle.hpp"
#include "tests/records/records_test_support.hpp"

namespace sc::records::test {

enum class Backend { Sqlite, Postgres };

inline std::string backend_name(const ::testing::TestParamInfo<Backend>& info) {
  return info.param == Backend::Sqlite ? "Sqlite" : "Postgres";
}

inline bool postgres_skipped() {
  const char* no = std::getenv("SKILLCOACH_NO_POSTGRES");
  return no != nullptr && std::string(no) == "1";
}

inline std::string pg_url(const std::string& database) {
  const char* host = std::getenv("SKILLCOACH_TEST_PG_HOST");
  if (host == nullptr) throw std::runtime_error("SKILLCOACH_TEST_PG_HOST is not set (run the tests with ctest)");
  return "postgresql://skillcoach@/" + database + "?host=" + host;
}

// An empty database `name` on the test server (dropped first if a previous run left it).
inline std::string fresh_pg_database(const std::string& name) {
  PgDb admin(pg_url("postgres"), 5);
  admin.exec("DROP DATABASE IF EXISTS " + name + " WITH (FORCE)");
  admin.exec("CREATE DATABASE " + name);
  return pg_url(name);
}

// `store` is the --store value; `local_dir` the desktop's data directory (a PostgreSQL store's spill file).
struct StoreUnderTest {
  Backend backend = Backend::Sqlite;
  std::string store;
  std::filesystem::path local_dir;

  std::unique_ptr<RecordStore> open(StoreOptions options = {}) const {
    return open_record_store(store, options, local_dir);
  }
};

inline StoreUnderTest fresh_store(Backend backend, const std::string& name) {
  const auto dir = fresh_dir(name);
  if (backend == Backend::Sqlite) return {backend, dir.string(), dir};
  return {backend, fresh_pg_database("t_" + name), dir};
}

// Base of the tests run on both stores.
class OnEachStore : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override {
    if (GetParam() == Backend::Postgres && postgres_skipped()) GTEST_SKIP() << "SKILLCOACH_NO_POSTGRES=1";
  }
  StoreUnderTest fresh(const std::string& name) const { return fresh_store(GetParam(), name); }
};

}  // namespace sc::records::test
