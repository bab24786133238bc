#pragma once
// TrainingSession: the headless orchestrator of one learner's session, which the trainer's screens (and the
// scripted `skillcoach learn` driver) drive. Per adaptive round:
//   Pretest (round 1 only)  Alg. 1 picks N_s diverse scenarios from the kit's expert pool; no ghost help.
//   Diagnosis               the pre-test (or, in later rounds, the last round's practice) is segmented and
//                           Alg. 2 ranks the skills; the study condition's curriculum is made and stored.
//   Drills                  the curriculum's items, each `sessions` times (the time-step budget); a demo
//                           may precede each, and the learner may add extra attempts ("try again").
//   Evaluation              fresh scenarios (never the pre-test's), no ghost.
//   Summary                 pre-test vs evaluation; Adaptive offers another round (back to Diagnosis).
// Every trial is committed to the record store the moment it is submitted, together with the point to
// resume from (progress_after), so a crash loses at most the trial being played; resume() rebuilds the
// session from the database (everything else is recomputed deterministically from the seed).
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "teaching/curricula/adaptive_curriculum.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/sessions/session_analysis.hpp"
#include "teaching/sessions/session_settings.hpp"
#include "teaching/sessions/session_summary.hpp"
#include "teaching/sessions/task_kit.hpp"

namespace sc {

using records::SessionPhase;

// ISO-8601 UTC text; tests pass a fixed clock, the app records::utc_timestamp_now.
using TimestampSource = std::function<std::string()>;

// When a trial was played (the screen knows; the orchestrator stores it).
struct TrialTimes {
  std::string started;
  std::string finished;
};

struct SubmittedTrial {
  double reward = 0.0;        // the kit's reward (<= 0, 0 = the expert's result)
  records::SaveResult saved;  // kept in the database, or pending with a message to show
};

// Work of another phase (analyse() during the pre-test, a practice trial at the summary, ...) is a bug in
// the caller and throws std::logic_error; bad input (settings, stored data, trial documents) InputError.
class TrainingSession {
 public:
  // Creates the learner (if new) and the session in `store`. Throws InputError for bad settings, an empty
  // expert pool or a store that cannot create the session.
  TrainingSession(const TaskKit& kit, records::RecordStore& store, SessionSettings settings, TimestampSource now);

  // Rebuilds the unfinished session `point` (from store.find_unfinished_session) where it stopped.
  // Throws InputError when the stored session belongs to another task or its trials do not fit.
  static std::unique_ptr<TrainingSession> resume(const TaskKit& kit, records::RecordStore& store,
                                                 const records::ResumePoint& point, TimestampSource now);

  std::int64_t session_id() const { return session_id_; }
  const SessionSettings& settings() const { return settings_; }
  const TaskKit& kit() const { return kit_; }
  SessionPhase phase() const { return progress_.phase; }
  int round() const { return progress_.round; }
  int item_index() const { return progress_.item_index; }  // within the phase
  bool finished() const { return finished_; }

  // ---- pre-test and evaluation (phase Pretest or Evaluation) ----
  const std::vector<int>& pretest_pool_indices() const { return pretest_pool_; }  // Alg. 1's picks
  std::vector<Json> pretest_scenarios() const;
  const std::vector<ExpertDemo>& eval_experts() const;  // this round's fresh scenarios with expert trials
  int test_count() const;                               // trials of the current test phase
  const ExpertDemo& test_expert() const;                // the current test item's scenario and expert trial
  const Json& test_scenario() const;                    // the scenario to play now
  const Json& test_expert_trial() const;  // its expert trial (for the "after" picture; not shown during tests)
  double test_time_limit() const;         // seconds, proportional to the expert's length
  SubmittedTrial submit_test_trial(const Json& trial, const TrialTimes& times);

  // ---- diagnosis (phase Diagnosis): runs Alg. 2 and makes the round's curriculum, then phase Drills ----
  void analyse();
  const ExpertiseEstimate& diagnosis() const;  // of the current round (after analyse)
  const Curriculum& curriculum() const;        // of the current round (after analyse)
  double last_analysis_seconds() const { return analysis_seconds_; }
  // The pre-test's diagnosis with where each target went wrong (for the diagnosis page's pictures); null before
  // the first analysis.
  const PlacedDiagnosis* pretest_places() const;
  CurriculumConfig curriculum_config() const;  // the kit's, with the session's round size

  // ---- drills (phase Drills) ----
  int practice_slot_count() const;  // sum of the curriculum's sessions
  // What the learner is told before practice: the most time the round's attempts may take (the sum of their
  // time limits; the demos come on top), in minutes, rounded up.
  int practice_minutes() const;
  int current_item() const;                    // item of the current slot
  int session_of_slot() const;                 // 1-based session number of the current slot within its item
  const PlayableDrill& drill(int item) const;  // projected once, cached
  double drill_time_limit(int item) const;
  // The expert's demo of an item (no score). Does not advance.
  records::SaveResult record_demo(int item, const Json& expert_trial, const TrialTimes& times);
  // A practice trial of the current slot; advances to the next slot (or to Evaluation after the last).
  SubmittedTrial submit_practice(const Json& trial, const TrialTimes& times);
  // "Try again" / "one more on this skill": one more attempt at `item` beyond the budget; does not advance.
  SubmittedTrial submit_extra_practice(int item, const Json& trial, const TrialTimes& times);
  // Ends practice early: skips the remaining slots of this round (recorded as progress only), to Evaluation.
  void skip_practice();

  // ---- summary (phase Summary) ----
  RoundSummary summary() const;
  bool can_continue() const { return settings_.condition == StudyCondition::Adaptive; }
  void start_next_round();  // Adaptive only: round + 1, back to Diagnosis
  void finish();            // marks the session finished

  // Trials submitted per round and kind (what resume reloads), for tests and the summary picture.
  const std::vector<Json>& pretest_trials() const { return pretest_trials_; }
  // The pre-test trials with the expert's segmentation and steps of their scenarios (what the diagnosis reads).
  std::vector<TestTrial> pretest_test_trials() const;
  const std::vector<Json>& eval_trials(int round) const;

 private:
  struct RoundState {
    ExpertiseEstimate diagnosis;
    Curriculum curriculum;
    std::vector<std::pair<int, Json>> practice;  // (item, trial) in play order
    std::vector<Json> eval;
    bool analysed = false;
  };
  TrainingSession(const TaskKit& kit, records::RecordStore& store, TimestampSource now);

  void select_pretest();
  CurriculumInputs curriculum_inputs() const;
  std::map<int, int> practice_per_skill() const;  // this round's played practice trials per target skill
  void compute_round(int round);                  // diagnosis + curriculum of `round` (no writes)
  RoundState& state(int round);
  const RoundState& state(int round) const;
  std::vector<int> slot_items(const Curriculum& curriculum) const;
  SubmittedTrial store_trial(records::TrialKind kind, std::optional<int> drill, const Json& trial,
                             std::optional<double> score, const TrialTimes& times,
                             std::optional<records::SessionProgress> after);
  void set_progress(records::SessionProgress progress, bool save);
  records::SessionProgress after_test_trial() const;
  records::SessionProgress after_practice_slot() const;
  void require_phase(SessionPhase phase, const char* what) const;

  const TaskKit& kit_;
  records::RecordStore& store_;
  TimestampSource now_;
  SessionSettings settings_;
  std::int64_t session_id_ = 0;
  records::SessionProgress progress_;
  bool finished_ = false;
  std::vector<int> pretest_pool_;
  std::vector<Json> pretest_trials_;
  std::vector<RoundState> rounds_;                               // index round - 1
  std::vector<AdaptiveRound> adaptive_rounds_;                   // Adaptive only, index round - 1
  mutable std::map<int, std::vector<ExpertDemo>> eval_experts_;  // per round, built on first use
  mutable std::map<std::pair<int, int>, PlayableDrill> drills_;  // (round, item)
  double analysis_seconds_ = 0.0;
  // The pre-test's diagnosis, computed once (with places) when a round is first computed after the pre-test; every
  // round's curriculum inputs read it. Keyed by the number of pre-test trials it was computed from.
  std::optional<PlacedDiagnosis> pretest_places_;
  std::size_t pretest_places_trials_ = 0;
};

}  // namespace sc
