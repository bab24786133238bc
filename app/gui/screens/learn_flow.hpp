#pragma once
// The trainer's state shared by its screens (learn_welcome -> learn_instructions -> learn_trial (pre-test)
// -> learn_diagnosis -> learn_trial (demo + practice) -> learn_trial (evaluation) -> learn_summary): the
// task kit, the learner database and the TrainingSession. Screens are recreated on every navigation; this
// object lives in AppServices::learn_flow for the whole run.
//
// Headless screenshots have no learner: learn_flow_for_screenshot() builds a deterministic session (fixed
// seed, fixed timestamps, scripted learner, a fresh database in a temporary directory) and plays it up to
// the phase the screen shows, so every screen of the flow has a golden with real data.
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include "app/gui/app_services.hpp"
#include "teaching/records/learner_store.hpp"
#include "teaching/sessions/training_session.hpp"
#include "teaching/tasks/task_kit_cache.hpp"

namespace sc {

class LearnFlow {
 public:
  std::string learner;                                  // typed on the welcome screen
  bool research = false;                                // Ctrl+Shift+R on the welcome screen
  StudyCondition condition = StudyCondition::Adaptive;  // research mode may change it
  // Parking lot in research mode (recorded with the session); learners get first_session_goal_region.
  GoalRegion research_lot = GoalRegion::StudyCorner;
  // Research mode: the study the learner joins (empty: none). Its randomisation assigns the condition at
  // enrolment, and no screen shows it (the learner must not know their arm).
  std::string study;
  // Round size (Ind. Drills, Adaptive), recorded with the session: drills for this many weakest skills ...
  int weak_skills = SessionSettings{}.weak_skills;
  int drills_per_weak_skill = SessionSettings{}.drills_per_weak_skill;  // ... this many unique drills each
  std::string message;  // last problem to show (one line), empty if none

  // The learner store, opened on first use. A store that could not be opened is not opened again by every
  // frame's query (a class server that does not answer costs its connect timeout each time): store()
  // rethrows that failure until retry_store(), which the learner's Continue calls.
  records::RecordStore& store(const AppServices& services);
  void retry_store() { store_failure_ = nullptr; }
  bool store_failed() const { return store_failure_ != nullptr; }
  TrainingSession* session() { return session_.get(); }

  // Starts a new session, or resumes the learner's unfinished one of this task when `resume` is set.
  void start(const AppServices& services, bool resume);
  // The learner's unfinished session of the current task, if any (for the welcome screen's offer).
  std::optional<records::ResumePoint> unfinished(const AppServices& services);

  bool headless_clock = false;        // fixed timestamps (screenshots)
  std::filesystem::path scratch_dir;  // screenshots' temporary database directory, removed with the flow

  LearnFlow() = default;
  LearnFlow(const LearnFlow&) = delete;
  LearnFlow& operator=(const LearnFlow&) = delete;
  ~LearnFlow();

 private:
  void join_study(records::RecordStore& db, const std::string& task, SessionSettings& settings) const;

  TaskKitCache kits_;  // built on first use (parking segments its pool once per lot)
  std::unique_ptr<records::RecordStore> store_;
  std::exception_ptr store_failure_;
  std::unique_ptr<TrainingSession> session_;
};

LearnFlow& learn_flow(AppServices& services);

// The screen that shows a session's current phase.
const char* screen_for_phase(SessionPhase phase);

// The trial screens' header: "Pre-test  2 of 5", "Drill demo  1 of 6", "Final test  3 of 5", or "Practice"
// for the result of a practice trial.
std::string learn_phase_title(const TrainingSession& s, bool demo, bool practice_result);

// "keyboard", "mouse-joystick", "gamepad", "mouse" (the device column of the trials table).
std::string device_key(const DeviceChoice& device);

// For headless screenshots: a deterministic session played by the scripted learner until `phase` (item
// `item` within it). Returns the flow (also stored in services.learn_flow).
LearnFlow& learn_flow_for_screenshot(AppServices& services, SessionPhase phase, int item = 0);

}  // namespace sc
