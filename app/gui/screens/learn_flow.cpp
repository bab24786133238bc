#include "app/gui/screens/learn_flow.hpp"

#include <unistd.h>

#include <filesystem>

#include "app/core/learn_scripted_learner.hpp"
#include "engine/core/error.hpp"
#include "teaching/records/data_dir.hpp"
#include "teaching/records/open_record_store.hpp"

namespace sc {
namespace {

TimestampSource clock_of(const LearnFlow& flow) {
  if (flow.headless_clock) return [] { return std::string("2024-05-01T12:00:00.000Z"); };
  return records::utc_timestamp_now;
}

}  // namespace

records::RecordStore& LearnFlow::store(const AppServices& services) {
  if (!store_) {
    if (store_failure_) std::rethrow_exception(store_failure_);
    const std::filesystem::path dir = services.options.data_dir.empty()
                                          ? records::default_data_dir()
                                          : std::filesystem::path(services.options.data_dir);
    try {
      store_ = services.options.store.empty() ? std::make_unique<records::LearnerStore>(dir)
                                              : records::open_record_store(services.options.store, {}, dir);
    } catch (const InputError&) {
      store_failure_ = std::current_exception();
      throw;
    }
  }
  return *store_;
}

std::optional<records::ResumePoint> LearnFlow::unfinished(const AppServices& services) {
  if (learner.empty()) return std::nullopt;
  return store(services).find_unfinished_session(learner, std::string(to_string(services.task)));
}

void LearnFlow::start(const AppServices& services, bool resume) {
  records::RecordStore& db = store(services);
  if (resume) {
    if (const auto point = unfinished(services)) {
      session_ = TrainingSession::resume(kits_.kit_of(point->session), db, *point, clock_of(*this));
      return;
    }
  }
  SessionSettings settings;
  settings.learner = learner;
  settings.device = device_key(services.device);
  settings.condition = research ? condition : StudyCondition::Adaptive;
  settings.seed = services.seed;
  settings.weak_skills = weak_skills;
  settings.drills_per_weak_skill = drills_per_weak_skill;
  if (services.task == TaskKind::parking)
    settings.goal_region = research ? research_lot : first_session_goal_region(db.session_count(learner, "parking"));
  const std::string task(to_string(services.task));
  if (research && !study.empty()) join_study(db, task, settings);
  session_ = std::make_unique<TrainingSession>(kits_.kit(task, settings.lot()), db, settings, clock_of(*this));
}

// One session per participant: a finished one ends the study for them (an unfinished one resumes above).
void LearnFlow::join_study(records::RecordStore& db, const std::string& task, SessionSettings& settings) const {
  for (const auto& s : db.study_sessions(study))
    if (s.session.learner == learner)
      throw InputError(learner, "already has a session in study \"" + study + "\" (session " +
                                    std::to_string(s.session.id) + "); resume it or ask the coordinator");
  const auto definition = db.study(study);
  if (!definition || definition->task != task)
    throw InputError("study \"" + study + "\"", "is not a " + task + " study in this database");
  const records::StudyParticipant participant = db.enrol(study, learner, clock_of(*this)());
  settings.condition = parse_condition(participant.condition);
  settings.study = study;
}

LearnFlow::~LearnFlow() {
  if (scratch_dir.empty()) return;
  session_.reset();  // close the database before its directory goes
  store_.reset();
  std::error_code ignored;
  std::filesystem::remove_all(scratch_dir, ignored);
}

LearnFlow& learn_flow(AppServices& services) {
  if (!services.learn_flow) services.learn_flow = std::make_shared<LearnFlow>();
  return *services.learn_flow;
}

const char* screen_for_phase(SessionPhase phase) {
  switch (phase) {
    case SessionPhase::Pretest:
    case SessionPhase::Drills:
    case SessionPhase::Evaluation:
      return "learn_trial";
    case SessionPhase::Diagnosis:
      return "learn_diagnosis";
    case SessionPhase::Summary:
      return "learn_summary";
  }
  return "learn_welcome";
}

std::string learn_phase_title(const TrainingSession& s, bool demo, bool practice_result) {
  const auto count = [](int i, int n) { return std::to_string(i + 1) + " of " + std::to_string(n); };
  if (practice_result) return "Practice";
  switch (s.phase()) {
    case SessionPhase::Pretest:
      return "Pre-test  " + count(s.item_index(), s.test_count());
    case SessionPhase::Evaluation:
      return "Final test  " + count(s.item_index(), s.test_count());
    case SessionPhase::Drills:
      return std::string(demo ? "Drill demo  " : "Drill practice  ") + count(s.item_index(), s.practice_slot_count());
    default:
      return "Trial";
  }
}

std::string device_key(const DeviceChoice& device) {
  switch (device.kind) {
    case DeviceKind::gamepad:
      return "gamepad";
    case DeviceKind::mouse_joystick:
      return "mouse-joystick";
    case DeviceKind::keyboard:
      return "keyboard";
    case DeviceKind::mouse_pen:
      return "mouse";
  }
  return "unknown";
}

LearnFlow& learn_flow_for_screenshot(AppServices& services, SessionPhase phase, int item) {
  LearnFlow& flow = learn_flow(services);
  if (flow.session()) return flow;
  flow.learner = "Ada";
  flow.headless_clock = true;
  // One directory per process (removed again with the flow): screenshot processes run in parallel (ctest -j)
  // and a shared directory let one process's session appear in another's review screenshot.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("skillcoach-screenshot-" + std::string(to_string(services.task)) + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  flow.scratch_dir = dir;
  services.options.data_dir = dir.string();
  flow.start(services, false);
  TrainingSession& s = *flow.session();
  ScriptedRunHooks hooks;
  hooks.hand = services.screenshot_learner_hand;
  hooks.stop = [phase, item](const TrainingSession& t) { return t.phase() == phase && t.item_index() >= item; };
  play_scripted_round(s, hooks);
  return flow;
}

}  // namespace sc
