// skillcoach learn: a whole training session played headless by the scripted learner
// (app/core/learn_scripted_learner.hpp) through the same TrainingSession orchestrator the trainer's
// screens drive, storing every trial in the learner database as it ends. Resumes the learner's unfinished
// session of the task when there is one. Used by the session and SIGKILL tests (the end-to-end tests through
// the screens run `skillcoach --script`), and handy to fill a database for the instructor review.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "app/core/learn_scripted_learner.hpp"
#include "engine/core/error.hpp"
#include "teaching/records/data_dir.hpp"
#include "teaching/records/open_record_store.hpp"
#include "teaching/sessions/training_session.hpp"
#include "teaching/tasks/task_kit_factory.hpp"

namespace sc::cli {
namespace {

struct LearnOptions {
  TaskKind task = TaskKind::parking;
  std::string data_dir;
  std::string store;  // empty: the SQLite store in data_dir
  std::string learner = "scripted learner";
  std::string condition = "adaptive";
  std::string device = "keyboard";
  int pretest = 5;
  int eval = 5;
  int rounds = 1;
  int weak_skills = 3;
  int drills_per_weak_skill = 2;
  std::string lot = "auto";  // parking: auto (study corner for a first session), study-corner, whole-lot
  unsigned long long seed = 20221128;
  int trial_delay_ms = 0;
  int learner_hand = 0;  // writing: the scripted learner's tests in this Omniglot drawer's letters
  std::string study;     // study mode: the study assigns the condition (and fixes the task); it is not printed
  bool task_given = false, condition_given = false;
};

void print_trial(const TrainingSession& s, const std::string& kind, const SubmittedTrial& kept) {
  std::printf("trial %s round %d reward %.4f %s\n", kind.c_str(), s.round(), kept.reward,
              kept.saved.stored ? "kept" : ("pending: " + kept.saved.message).c_str());
  std::fflush(stdout);
}

// The round's practice before it starts: what a learner is told, and the budget a researcher checks. In a
// study the participant must not learn their condition: only the round's size is printed.
void print_plan(const TrainingSession& s) {
  const Curriculum& c = s.curriculum();
  if (!s.settings().study.empty()) {
    std::printf("plan round %d trials %d minutes %d\n", s.round(), c.trials(), s.practice_minutes());
    std::fflush(stdout);
    return;
  }
  std::printf("plan round %d condition %s trials %d steps %d budget %d (reference: %s) minutes %d\n", s.round(),
              std::string(condition_key(c.condition)).c_str(), c.trials(), c.total_steps(), c.budget_steps,
              budget_reference(s.curriculum_config()).c_str(), s.practice_minutes());
  if (!s.diagnosis().learner_hand.empty()) std::printf("  learner's hand: %s\n", s.diagnosis().learner_hand.c_str());
  for (std::size_t i = 0; i < c.items.size(); ++i) {
    const PracticeItem& item = c.items[i];
    std::string targets;
    for (int m : item.target_skills) {
      if (!targets.empty()) targets += ',';
      targets += std::to_string(m);
    }
    std::printf("  item %zu %s targets %s sessions %d steps %d\n", i, std::string(practice_kind_key(item.kind)).c_str(),
                targets.c_str(), item.sessions, item.steps());
  }
  std::fflush(stdout);
}

// "(drilled)" only for skills practised in this round, with how many trials.
void print_skills(const TrainingSession& s, const RoundSummary& summary) {
  for (const SkillChange& c : summary.skills) {
    if (!c.seen && !c.drilled) continue;
    std::printf("  skill %d %s: %.3f -> %.3f", c.skill, s.kit().describe_skill(c.skill).c_str(), c.before, c.after);
    if (c.drilled) std::printf(" (drilled, %d trial%s)", c.practice_trials, c.practice_trials == 1 ? "" : "s");
    std::printf("\n");
  }
}

// Exit code of a session whose records are not all in the database: the work is not lost while the spill
// file holds it, but the command must not report success.
constexpr int kExitRecordsNotSaved = 3;

// A last attempt to store what is pending; says what is not stored and where it is.
int report_unsaved(records::RecordStore& store) {
  const auto result = store.flush();
  if (result.pending == 0) return 0;
  std::fprintf(stderr, "skillcoach: error: %s; %s\n", result.message.c_str(),
               store.pending_spilled() ? "the next start of SkillCoach on this data directory saves them"
                                       : "they are lost when this program ends");
  return kExitRecordsNotSaved;
}

// The new session's settings; the lot is the learner's first-session default unless --lot names one.
SessionSettings new_settings(const LearnOptions& o, const records::RecordStore& store) {
  SessionSettings settings;
  settings.learner = o.learner;
  settings.device = o.device;
  settings.condition = parse_condition(o.condition);
  settings.pretest_count = o.pretest;
  settings.eval_count = o.eval;
  settings.seed = o.seed;
  settings.weak_skills = o.weak_skills;
  settings.drills_per_weak_skill = o.drills_per_weak_skill;
  if (o.task == TaskKind::parking)
    settings.goal_region = o.lot == "auto"
                               ? first_session_goal_region(store.session_count(o.learner, to_string(TaskKind::parking)))
                               : parse_goal_region(o.lot, "--lot");
  return settings;
}

std::string lot_words(const SessionSettings& settings) {
  if (!settings.goal_region) return "";
  return *settings.goal_region == GoalRegion::StudyCorner ? " on the study corner (goals in spots 12-14)"
                                                          : " on the whole lot";
}

// Study mode: the learner is enrolled (if not yet) and gets the study's task and their assigned condition.
// A participant has one session in the study: an unfinished one resumes, a finished one ends the study for
// them.
LearnOptions enrol_in_study(LearnOptions o, records::RecordStore& store) {
  const auto study = store.study(o.study);
  if (!study) throw InputError(store.database_path().string(), "has no study \"" + o.study + "\"");
  if (o.condition_given) throw InputError("--condition", "cannot be combined with --study: the study assigns it");
  const TaskKind task = parse_task_kind(study->task, "study task");
  if (o.task_given && o.task != task)
    throw InputError("--task", "study \"" + o.study + "\" is a " + study->task + " study");
  o.task = task;
  const auto point = store.find_unfinished_session(o.learner, to_string(o.task));
  if (point && point->session.study != o.study)
    throw InputError(o.learner, "has an unfinished " + study->task + " session (" + std::to_string(point->session.id) +
                                    ") outside study \"" + o.study + "\"; finish it first");
  for (const auto& s : store.study_sessions(o.study))
    if (s.session.learner == o.learner && s.session.finished)
      throw InputError(
          o.learner, "has already completed study \"" + o.study + "\" (session " + std::to_string(s.session.id) + ")");
  const records::StudyParticipant participant = store.enrol(o.study, o.learner, records::utc_timestamp_now());
  o.condition = participant.condition;
  std::printf("study \"%s\": participant %d\n", o.study.c_str(), participant.seq);
  return o;
}

int run(LearnOptions o) {
  if (o.task == TaskKind::writing && o.lot != "auto")
    throw InputError("--lot", "is a parking setting (writing has no lot)");
  const std::filesystem::path data_dir =
      o.data_dir.empty() ? records::default_data_dir() : std::filesystem::path(o.data_dir);
  const auto opened = records::open_record_store(o.store.empty() ? data_dir.string() : o.store, {}, data_dir);
  records::RecordStore& store = *opened;
  if (!store.open_message().empty()) std::fprintf(stderr, "skillcoach: warning: %s\n", store.open_message().c_str());
  if (!o.study.empty()) o = enrol_in_study(o, store);
  const auto point = store.find_unfinished_session(o.learner, to_string(o.task));
  SessionSettings settings = point ? settings_of_session(point->session) : new_settings(o, store);
  if (!point) settings.study = o.study;
  const auto kit = make_task_kit(o.task, {}, settings.lot());
  if (!kit->extractor_notice().empty()) std::fprintf(stderr, "skillcoach: note: %s\n", kit->extractor_notice().c_str());
  std::unique_ptr<TrainingSession> session;
  if (point) {
    session = TrainingSession::resume(*kit, store, *point, records::utc_timestamp_now);
    std::printf("resumed session %lld%s at round %d, %s, item %d\n", static_cast<long long>(session->session_id()),
                lot_words(session->settings()).c_str(), session->round(),
                std::string(records::to_string(session->phase())).c_str(), session->item_index());
    if (session->phase() != SessionPhase::Pretest && session->phase() != SessionPhase::Diagnosis) print_plan(*session);
  } else {
    session = std::make_unique<TrainingSession>(*kit, store, settings, records::utc_timestamp_now);
    std::printf("started session %lld%s\n", static_cast<long long>(session->session_id()),
                lot_words(session->settings()).c_str());
  }
  std::fflush(stdout);
  ScriptedRunHooks hooks;
  hooks.after_trial = [&](const TrainingSession& s, const std::string& kind, const SubmittedTrial& kept) {
    print_trial(s, kind, kept);
    if (o.trial_delay_ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(o.trial_delay_ms));
  };
  hooks.after_analysis = print_plan;
  hooks.hand = o.learner_hand;
  while (true) {
    play_scripted_round(*session, hooks);
    const RoundSummary summary = session->summary();
    std::printf("summary round %d pretest %.4f eval %.4f improvement %+.4f practice %d analysis %.3f s\n",
                summary.round, summary.pretest_mean, summary.eval_mean, summary.improvement, summary.practice_trials,
                session->last_analysis_seconds());
    print_skills(*session, summary);
    if (session->round() >= o.rounds || !session->can_continue()) break;
    session->start_next_round();
  }
  session->finish();
  std::printf("finished session %lld\n", static_cast<long long>(session->session_id()));
  std::fflush(stdout);
  return report_unsaved(store);
}

CommandRunner setup_learn(CLI::App& sub) {
  auto o = std::make_shared<LearnOptions>();
  CLI::Option* task = add_task_option(sub, o->task, "parking (default) or writing");
  sub.add_option("--data-dir", o->data_dir, "Directory of the learner database (default: XDG data directory)");
  sub.add_option("--store", o->store,
                 "Where the records go instead: a postgresql:// URL shared by a class (docs/database.md); "
                 "--data-dir then keeps the records the server could not take yet");
  sub.add_option("--learner", o->learner, "Learner's name")->capture_default_str();
  CLI::Option* condition =
      sub.add_option("--condition", o->condition, "Study condition (research mode)")->capture_default_str();
  sub.add_option("--study", o->study,
                 "Study mode: enrol the learner (if not yet) and train in the condition the study assigns (not shown)");
  sub.add_option("--device", o->device, "Device recorded with the trials")->capture_default_str();
  sub.add_option("--pretest", o->pretest, "Pre-test scenarios (N_s)")->capture_default_str();
  sub.add_option("--eval", o->eval, "Evaluation scenarios per round")->capture_default_str();
  sub.add_option("--weak-skills", o->weak_skills, "Ind. Drills / Adaptive: weakest skills drilled per round")
      ->capture_default_str();
  sub.add_option("--drills-per-skill", o->drills_per_weak_skill, "Ind. Drills / Adaptive: unique drills per weak skill")
      ->capture_default_str();
  sub.add_option("--lot", o->lot,
                 "Parking goals: auto (the study corner for a learner's first parking session, then the whole lot), "
                 "study-corner or whole-lot; recorded with the session")
      ->capture_default_str();
  sub.add_option("--rounds", o->rounds, "Adaptive rounds to play")->capture_default_str()->check(CLI::Range(1, 20));
  sub.add_option("--seed", o->seed, "Session seed")->capture_default_str();
  sub.add_option("--trial-delay-ms", o->trial_delay_ms, "Pause after each kept trial (crash tests)")
      ->check(CLI::Range(0, 60000));
  sub.add_option("--learner-hand", o->learner_hand,
                 "Writing: the scripted learner writes its tests in this Omniglot drawer's letters (0: the guide's)")
      ->check(CLI::Range(0, 15));
  return [o, task, condition] {
    o->task_given = task->count() > 0;
    o->condition_given = condition->count() > 0;
    return run(*o);
  };
}

const CommandRegistration kLearnCommandRegistration{
    {"learn", "Play a whole training session headless with a scripted learner",
     "skillcoach learn --task parking --data-dir /tmp/sc --learner ada", setup_learn}};

}  // namespace
}  // namespace sc::cli
