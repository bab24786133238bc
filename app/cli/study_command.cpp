// skillcoach study create|enrol|status: a study's coordinator defines the study (its conditions, the target
// number of participants per condition and the randomisation seed), enrols participants (each gets the
// next condition of the seeded permuted-block sequence, teaching/records/study_assignment.hpp, which is
// not printed: participants may see this screen) and follows enrolment per condition against the target.
// `status --participants` shows who is in which condition (the coordinator's view).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/error.hpp"
#include "teaching/curricula/study_condition.hpp"
#include "teaching/records/open_record_store.hpp"
#include "teaching/records/record_studies.hpp"
#include "teaching/studies/study_analysis.hpp"

namespace sc::cli {
namespace {

struct StudyOptions {
  std::string store;
  std::string name;
  TaskKind task = TaskKind::parking;
  std::vector<std::string> conditions;
  int per_condition = 0;
  unsigned long long seed = 0;
  std::string learner;
  bool participants = false;
};

records::StudyDefinition require_study(const records::RecordStore& store, const std::string& name) {
  auto study = store.study(name);
  if (!study) throw InputError(store.database_path().string(), "has no study \"" + name + "\"");
  return *study;
}

int create(const StudyOptions& o, bool seed_given) {
  records::StudyDefinition study;
  study.name = o.name;
  study.task = std::string(to_string(o.task));
  for (const std::string& c : o.conditions) study.conditions.emplace_back(condition_key(parse_condition(c)));
  study.target_per_condition = o.per_condition;
  // An unguessable default: who knows the seed can foresee every assignment. It is stored with the study.
  study.seed = seed_given ? o.seed : (std::uint64_t{std::random_device{}()} << 32) ^ std::random_device{}();
  study.created = records::utc_timestamp_now();
  const auto store = records::open_record_store(o.store);
  store->create_study(study);
  std::printf("created study \"%s\" in %s: %s, %zu conditions x %d participants, seed %llu\n", study.name.c_str(),
              store->database_path().string().c_str(), study.task.c_str(), study.conditions.size(),
              study.target_per_condition, static_cast<unsigned long long>(study.seed));
  return 0;
}

int enrol(const StudyOptions& o) {
  const auto store = records::open_record_store(o.store);
  const records::StudyDefinition study = require_study(*store, o.name);
  const auto before = store->study_participants(o.name).size();
  const records::StudyParticipant p = store->enrol(o.name, o.learner, records::utc_timestamp_now());
  const bool is_new = store->study_participants(o.name).size() > before;
  std::printf("%s \"%s\" in study \"%s\" as participant %d of %d (the condition is not shown)\n",
              is_new ? "enrolled" : "already enrolled:", p.learner.c_str(), study.name.c_str(), p.seq,
              study.capacity());
  return 0;
}

void print_study(const records::RecordStore& store, const records::StudyDefinition& study, bool participants) {
  const auto enrolled = store.study_participants(study.name);
  const auto outcomes = participant_outcomes(enrolled, store.study_sessions(study.name));
  std::printf("study \"%s\": %s, seed %llu, created %s\n", study.name.c_str(), study.task.c_str(),
              static_cast<unsigned long long>(study.seed), study.created.c_str());
  std::printf("  %-18s %9s %7s %10s\n", "condition", "enrolled", "target", "completed");
  int total_completed = 0;
  for (const auto& row : records::enrolment_by_condition(study, enrolled)) {
    int completed = 0;
    for (const auto& o : outcomes) completed += o.participant.condition == row.condition && o.counted() ? 1 : 0;
    total_completed += completed;
    std::printf("  %-18s %9d %7d %10d\n", row.condition.c_str(), row.enrolled, row.target, completed);
  }
  std::printf("  %-18s %9zu %7d %10d%s\n", "total", enrolled.size(), study.capacity(), total_completed,
              static_cast<int>(enrolled.size()) >= study.capacity() ? "  (full)" : "");
  if (!participants) return;
  for (const auto& o : outcomes) {
    std::printf("  #%-3d %-24s %-16s %s\n", o.participant.seq, o.participant.learner.c_str(),
                o.participant.condition.c_str(),
                o.counted() ? ("session " + std::to_string(*o.session_id) + " counted").c_str() : o.excluded.c_str());
  }
}

int status(const StudyOptions& o) {
  const auto opened = records::open_record_store(o.store, records::StoreOptions{.read_only = true});
  const records::RecordStore& store = *opened;
  if (!o.name.empty()) {
    print_study(store, require_study(store, o.name), o.participants);
    return 0;
  }
  const auto studies = store.list_studies();
  if (studies.empty()) std::printf("no studies in %s\n", store.database_path().string().c_str());
  for (const auto& study : studies) print_study(store, study, o.participants);
  return 0;
}

void add_store_option(CLI::App& app, std::string& store) {
  app.add_option("--store", store,
                 "Data directory, its skillcoach.db, or a postgresql:// URL (a shared server; see docs/database.md) "
                 "(default: $XDG_DATA_HOME/skillcoach or ~/.local/share/skillcoach)");
}

CommandRunner setup_study(CLI::App& sub) {
  auto o = std::make_shared<StudyOptions>();
  sub.require_subcommand(1);
  CLI::App* create_cmd = sub.add_subcommand("create", "Define a study: task, conditions, participants per condition");
  add_store_option(*create_cmd, o->store);
  create_cmd->add_option("--name", o->name, "The study's name")->required();
  add_task_option(*create_cmd, o->task, "parking or writing")->required();
  create_cmd->add_option("--conditions", o->conditions, "Conditions, comma-separated (e.g. skills,time-heuristic)")
      ->required()
      ->delimiter(',');
  create_cmd->add_option("--per-condition", o->per_condition, "Target participants per condition")
      ->required()
      ->check(CLI::Range(1, 10000));
  CLI::Option* seed = create_cmd->add_option(
      "--seed", o->seed, "Randomisation seed (default: drawn at random and stored; keep it secret)");
  CLI::App* enrol_cmd = sub.add_subcommand("enrol", "Enrol a participant (the condition is assigned, not shown)");
  add_store_option(*enrol_cmd, o->store);
  enrol_cmd->add_option("--study", o->name, "The study")->required();
  enrol_cmd->add_option("--learner", o->learner, "The participant's name")->required();
  CLI::App* status_cmd = sub.add_subcommand("status", "Enrolment per condition against the target");
  add_store_option(*status_cmd, o->store);
  status_cmd->add_option("--study", o->name, "The study (default: every study)");
  status_cmd->add_flag("--participants", o->participants, "List every participant with their condition");
  return [o, create_cmd, enrol_cmd, seed] {
    if (create_cmd->parsed()) return create(*o, seed->count() > 0);
    if (enrol_cmd->parsed()) return enrol(*o);
    return status(*o);
  };
}

const CommandRegistration kStudyCommandRegistration{
    {"study", "Run a study: create it, enrol participants (balanced randomisation), see enrolment",
     "skillcoach study create --store DIR --name pilot --task parking --conditions skills,time-heuristic,"
     "full-trajectory --per-condition 20",
     setup_study}};

}  // namespace
}  // namespace sc::cli
