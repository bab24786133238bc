// The learner database (teaching/records): a fuzzed file is put where the trainer keeps skillcoach.db and
// opened with the LearnerStore. It must be refused with InputError or read: the instructor review
// queries and the export (`skillcoach export`) run over everything it holds. First byte (mod 2):
//   0  read-only store (review/export path: never writes);
//   1  writable store (the trainer's path): additionally starts a session and records a trial into it,
//      which on a damaged-but-accepted file must fail with InputError or be kept pending, never crash.
// Run with TMPDIR on a tmpfs (e.g. /dev/shm): every write is fsynced.
#include <system_error>

#include "engine/core/error.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/records/records_export.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using namespace sc::records;

void review_and_export(const LearnerStore& store) {
  for (const auto& learner : store.list_learners()) {
    for (const auto& summary : learner.sessions) {
      const auto id = summary.session.id;
      (void)store.session(id);
      (void)store.trials_of_session(id);
      (void)store.diagnoses_of_session(id);
      (void)store.curricula_of_session(id);
    }
  }
  sc::write_json_file(sc::fuzz::scratch_dir() / "export.json", export_records(store).doc);  // as export_database
}

void record_one_trial(LearnerStore& store) {
  const auto session = store.begin_session({"Fuzz", "parking", "adaptive", 7, "{}", "2024-05-01T10:00:00.000Z", ""});
  TrialRecord trial;
  trial.session_id = session;
  trial.task = "parking";
  trial.scenario_json = R"({"heading0":0.7,"goal":{"spot":3}})";
  trial.trajectory_json = R"({"task":"parking","scenario":{"heading0":0.7,"goal":{"spot":3}},"actions":[[0,0]]})";
  trial.score = -1.0;
  trial.device = "keyboard";
  trial.started = "2024-05-01T10:00:00.000Z";
  trial.finished = "2024-05-01T10:00:20.000Z";
  (void)store.record_trial(trial);
  (void)store.find_unfinished_session("Fuzz", "parking");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto dir = sc::fuzz::scratch_dir() / "db";
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  std::filesystem::create_directories(dir);
  sc::fuzz::write_bytes(dir / LearnerStore::kDatabaseFileName, sc::fuzz::as_text(data + 1, size - 1));
  const bool writable = data[0] % 2 == 1;
  try {
    LearnerStore store(dir, StoreOptions{.read_only = !writable, .busy_timeout_ms = 0});
    (void)store.schema_version();
    review_and_export(store);
    if (writable) {
      record_one_trial(store);
      review_and_export(store);
    }
  } catch (const sc::InputError&) {}
  return 0;
}
