// The pending-writes spill file ("skillcoach.db.pending.json", teaching/records/pending_writes.hpp): the
// records a store could not write yet, replayed into the database by the next store that opens it. The
// fuzzed file is placed next to a real database holding one learner and session 1, then the store is
// opened: it must replay it, or move an unreadable file aside with a message, never crash.
// Run with TMPDIR on a tmpfs (e.g. /dev/shm): every write is fsynced.
#include <fstream>
#include <iterator>
#include <system_error>

#include "engine/core/error.hpp"
#include "teaching/records/learner_store.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using namespace sc::records;

// The bytes of a database with one learner and one session (id 1), made once per process.
const std::string& template_database() {
  static const std::string bytes = [] {
    const auto dir = sc::fuzz::scratch_dir() / "template";
    std::filesystem::remove_all(dir);
    {
      LearnerStore store(dir);
      store.begin_session({"Fuzz", "parking", "adaptive", 7, "{}", "2024-05-01T10:00:00.000Z", ""});
    }  // closing the last connection checkpoints the WAL into the file
    std::ifstream in(dir / LearnerStore::kDatabaseFileName, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& database = template_database();
  const auto dir = sc::fuzz::scratch_dir() / "db";
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  std::filesystem::create_directories(dir);
  sc::fuzz::write_bytes(dir / LearnerStore::kDatabaseFileName, database);
  sc::fuzz::write_bytes(dir / "skillcoach.db.pending.json", sc::fuzz::as_text(data, size));
  try {
    LearnerStore store(dir);
    (void)store.trials_of_session(1);
    (void)store.find_unfinished_session("Fuzz");
    (void)store.flush();
  } catch (const sc::InputError&) {}
  return 0;
}
