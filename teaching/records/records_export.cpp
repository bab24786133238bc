#include "teaching/records/records_export.hpp"

#include "teaching/records/record_json.hpp"

namespace sc::records {
namespace {

Json optional_number(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

Json export_session(const LearnerStore& store, const SessionSummary& summary) {
  const auto id = summary.session.id;
  Json session = session_to_json(summary.session);
  session["summary"] = {{"trial_count", summary.trial_count},
                        {"pretest_mean", optional_number(summary.pretest_mean)},
                        {"eval_mean", optional_number(summary.eval_mean)},
                        {"improvement", optional_number(summary.improvement)}};
  Json trials = Json::array();
  for (const auto& trial : store.trials_of_session(id)) trials.push_back(trial_to_json(trial.record, trial.seq));
  Json diagnoses = Json::array();
  for (const auto& diagnosis : store.diagnoses_of_session(id)) diagnoses.push_back(diagnosis_to_json(diagnosis));
  Json curricula = Json::array();
  for (const auto& curriculum : store.curricula_of_session(id)) curricula.push_back(curriculum_to_json(curriculum));
  session["trials"] = std::move(trials);
  session["diagnoses"] = std::move(diagnoses);
  session["curricula"] = std::move(curricula);
  return session;
}

}  // namespace

Json export_records(const LearnerStore& store) {
  Json learners = Json::array();
  for (const auto& learner : store.list_learners()) {
    Json sessions = Json::array();
    for (const auto& summary : learner.sessions) sessions.push_back(export_session(store, summary));
    learners.push_back({{"name", learner.name}, {"created", learner.created}, {"sessions", std::move(sessions)}});
  }
  return {{"format", kExportFormat},
          {"version", kExportVersion},
          {"schema_version", store.schema_version()},
          {"learners", std::move(learners)}};
}

std::size_t export_database(const std::filesystem::path& data_dir, const std::filesystem::path& out) {
  const LearnerStore store(data_dir, StoreOptions{.read_only = true});
  const Json doc = export_records(store);
  std::size_t trials = 0;
  for (const auto& learner : doc["learners"])
    for (const auto& session : learner["sessions"]) trials += session["trials"].size();
  write_json_file(out, doc, 1);
  return trials;
}

}  // namespace sc::records
