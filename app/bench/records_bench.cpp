// Learner database: latency of keeping one finished trial (a ~30 KB parking trajectory file), i.e. what
// the trainer waits for between two trials. The store commits each trial in its own transaction with
// synchronous=FULL (an fsync of the WAL per trial); the second benchmark runs the same write with
// synchronous=NORMAL to show what the durability costs.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "engine/core/json_file.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/records/record_writes.hpp"
#include "teaching/records/schema_migrations.hpp"
#include "teaching/records/sqlite_handle.hpp"

namespace {

using namespace sc::records;

// 620 steps (about two minutes at 5 Hz) with actions, states and rewards: about 30 KB of JSON.
constexpr int kSteps = 620;

// A parking trajectory-file document: actions, states and rewards for `steps` steps.
std::string realistic_trajectory(int steps) {
  sc::Json actions = sc::Json::array(), states = sc::Json::array(), rewards = sc::Json::array();
  for (int i = 0; i < steps; ++i) {
    const double t = 0.2 * i;
    actions.push_back({std::round(std::sin(0.3 * t) * 1e4) / 1e4, std::round(std::cos(0.2 * t) * 1e4) / 1e4});
    states.push_back({std::round((12.0 - 0.1 * t) * 1e3) / 1e3, std::round((4.0 + std::sin(t)) * 1e3) / 1e3,
                      std::round(0.01 * t * 1e3) / 1e3, std::round(std::cos(t) * 1e3) / 1e3});
    rewards.push_back(std::round(-0.05 * t * 1e4) / 1e4);
  }
  sc::Json doc = {
      {"task", "parking"},
      {"scenario", {{"heading0", 0.7}, {"goal", {{"x", 3.0}, {"y", -2.0}, {"heading", 1.57}}}, {"variant", "classic"}}},
      {"actions", actions},
      {"states", states},
      {"rewards", rewards},
      {"success", true},
      {"source", "learner"}};
  return doc.dump();
}

TrialRecord bench_trial(std::int64_t session_id, const std::string& trajectory) {
  TrialRecord t;
  t.session_id = session_id;
  t.kind = TrialKind::Practice;
  t.task = "parking";
  t.scenario_json = R"({"heading0":0.7,"goal":{"x":3.0,"y":-2.0,"heading":1.57},"variant":"classic"})";
  t.trajectory_json = trajectory;
  t.score = -2.5;
  t.device = "gamepad";
  t.started = "2024-05-01T10:00:00.000Z";
  t.finished = "2024-05-01T10:01:30.000Z";
  t.progress_after = SessionProgress{1, SessionPhase::Drills, 1};
  return t;
}

std::filesystem::path bench_dir(const char* name) {
  auto dir = std::filesystem::temp_directory_path() / ("skillcoach-bench-" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

void BM_RecordTrial(benchmark::State& state) {
  const auto dir = bench_dir("store");
  const std::string trajectory = realistic_trajectory(kSteps);
  {
    LearnerStore store(dir);
    const auto session = store.begin_session({"Bench", "parking", "adaptive", 1, "{}", "2024-05-01T10:00:00.000Z", ""});
    const auto trial = bench_trial(session, trajectory);
    for (auto _ : state) {
      const auto result = store.record_trial(trial);
      if (!result.stored) state.SkipWithError(result.message.c_str());
    }
  }
  state.counters["trajectory_bytes"] = static_cast<double>(trajectory.size());
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * trajectory.size()));
  std::filesystem::remove_all(dir.parent_path());
}
BENCHMARK(BM_RecordTrial)->Name("records/insert_trial_30kB")->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RecordTrialSyncNormal(benchmark::State& state) {
  const auto dir = bench_dir("normal");
  std::filesystem::create_directories(dir);
  const std::string trajectory = realistic_trajectory(kSteps);
  {
    SqliteDb db(dir / "skillcoach.db", SqliteDb::Mode::ReadWriteCreate);
    db.query_text("PRAGMA journal_mode = WAL");
    db.exec("PRAGMA synchronous = NORMAL; PRAGMA foreign_keys = ON");
    migrate(db, schema_migrations(), "bench");
    const auto learner = insert_learner_if_new(db, "Bench", "t");
    const auto session = insert_session(db, learner, {"Bench", "parking", "adaptive", 1, "{}", "t", ""});
    TrialWrite write{bench_trial(session, trajectory), 0};
    for (auto _ : state) {
      ++write.seq;
      SqliteTransaction transaction(db);
      apply_write(db, write);
      transaction.commit();
    }
  }
  std::filesystem::remove_all(dir.parent_path());
}
BENCHMARK(BM_RecordTrialSyncNormal)
    ->Name("records/insert_trial_30kB_sync_normal")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
