#pragma once
// What the learner store keeps: the records the trainer writes during a session and the rows the
// instructor review reads back. JSON payloads (scenario, trajectory, expertise, ...) travel as text:
// the store checks that they are valid JSON but does not interpret them (their formats belong to the
// tasks and the teaching engine). Timestamps are ISO-8601 UTC text supplied by the caller
// (utc_timestamp_now() for real sessions; fixed strings keep tests deterministic).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sc::records {

enum class TrialKind { Pretest, Demo, Practice, Eval };
// Where the trainer's flow is within one adaptive round (the trainer's screens).
enum class SessionPhase { Pretest, Diagnosis, Drills, Evaluation, Summary };

std::string_view to_string(TrialKind kind);
std::string_view to_string(SessionPhase phase);
// Throw sc::InputError naming `source` for an unknown name.
TrialKind trial_kind_from_string(std::string_view name, std::string_view source);
SessionPhase session_phase_from_string(std::string_view name, std::string_view source);

// Where a session resumes: the next item to do. Saved with every trial in the same transaction.
struct SessionProgress {
  int round = 1;                               // adaptive round, 1-based
  SessionPhase phase = SessionPhase::Pretest;  // the screen to resume on
  int item_index = 0;                          // next item within the phase (scenario, drill trial, ...)
  bool operator==(const SessionProgress&) const = default;
};

struct NewSession {
  std::string learner;               // learner's name; created if new
  std::string task;                  // "parking" or "writing"
  std::string condition;             // study condition / curriculum name ("adaptive", "ind_drills", ...)
  std::uint64_t seed = 0;            // regenerates the session's scenarios on resume
  std::string settings_json = "{}";  // free-form session settings (N_s, time limits, ...)
  std::string started;               // ISO-8601 UTC
  // The study the session belongs to (study_records.hpp), empty for none. The learner must be enrolled
  // in it and `condition` and `task` must be the study's assignment.
  std::string study;
};

struct TrialRecord {
  std::int64_t session_id = 0;
  TrialKind kind = TrialKind::Pretest;
  int round = 1;
  std::optional<int> drill_index;  // demo/practice: index of the drill in the round's curriculum
  std::string task;
  std::string scenario_json;    // the scenario object of the trajectory file
  std::string trajectory_json;  // the whole trajectory-file document
  std::optional<double> score;  // absent for demos
  std::string device;           // "gamepad", "mouse-joystick", "keyboard", "mouse", "trackpad", ...
  std::string started;
  std::string finished;
  // Where to resume once this trial is kept; written atomically with the trial.
  std::optional<SessionProgress> progress_after;
};

struct StoredTrial {
  std::int64_t id = 0;
  int seq = 0;  // 1-based order within the session
  TrialRecord record;
};

struct DiagnosisRecord {
  std::int64_t session_id = 0;
  int round = 1;
  std::string expertise_json;  // per-skill expertise vector
  std::string targets_json;    // the skills chosen for drilling
  std::string extractor;       // SkillExtractor name
  std::string model_id;        // model file / hash; empty for model-free extractors
  std::string created;
};

struct DrillRecord {
  int index = 0;
  std::string skills_json;   // the drill's skill n-gram
  std::string content_json;  // what the player needs to play it (ghost path, scenario, budget, ...)
};

struct CurriculumRecord {
  std::int64_t session_id = 0;
  int round = 1;
  std::string condition;
  std::string items_json;  // the curriculum's item list (drills and budgets in order)
  std::vector<DrillRecord> drills;
  std::string created;
};

struct SessionRow {
  std::int64_t id = 0;
  std::string learner;
  std::string task;
  std::string condition;
  std::uint64_t seed = 0;
  std::string settings_json;
  std::string started;
  std::optional<std::string> finished;
  SessionProgress progress;
  std::string study;  // empty: not part of a study
};

// An unfinished session and where it stopped.
struct ResumePoint {
  SessionRow session;
  int trials_done = 0;  // trials kept so far (in the database or still pending)
};

// One line of the instructor's session browser.
struct SessionSummary {
  SessionRow session;
  int trial_count = 0;
  std::optional<double> pretest_mean;  // mean score of the pre-test trials of the first round
  std::optional<double> eval_mean;     // mean score of the evaluation trials of the last round that has any
  std::optional<double> improvement;   // eval_mean - pretest_mean
};

struct LearnerOverview {
  std::int64_t id = 0;
  std::string name;
  std::string created;
  std::vector<SessionSummary> sessions;  // oldest first
};

// Outcome of a write: either kept in the database, or kept pending with a one-line message saying why
// and where the pending copy is.
struct SaveResult {
  bool stored = false;      // this record is in the database
  std::size_t pending = 0;  // records still waiting for the database (this one included if not stored)
  std::string message;      // empty when everything is stored
};

// Current UTC time as "2024-05-01T12:34:56.789Z".
std::string utc_timestamp_now();

}  // namespace sc::records
