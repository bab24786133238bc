#include "teaching/records/records_export.hpp"

#include "engine/core/error.hpp"
#include "teaching/records/record_json.hpp"

namespace sc::records {
namespace {

Json optional_number(const std::optional<double>& value) { return value ? Json(*value) : Json(nullptr); }

// Converts the records of one session; a damaged row (JSON that no longer parses) is left out and named in
// `problems`, so one bad row never costs the learner the export of everything else.
class SessionExporter {
 public:
  SessionExporter(const RecordStore& store, RecordsExport& out) : store_(store), out_(out) {}

  Json session(const SessionSummary& summary) {
    const auto id = summary.session.id;
    Json session = {{"id", id}};
    convert("session " + std::to_string(id), [&] { session = session_to_json(summary.session); });
    session["summary"] = {{"trial_count", summary.trial_count},
                          {"pretest_mean", optional_number(summary.pretest_mean)},
                          {"eval_mean", optional_number(summary.eval_mean)},
                          {"improvement", optional_number(summary.improvement)}};
    const std::string where = "session " + std::to_string(id) + ", ";
    Json trials = Json::array();
    for (const auto& trial : store_.trials_of_session(id))
      convert(where + "trial " + std::to_string(trial.seq),
              [&] { trials.push_back(trial_to_json(trial.record, trial.seq)); });
    Json diagnoses = Json::array();
    for (const auto& d : store_.diagnoses_of_session(id))
      convert(where + "diagnosis of round " + std::to_string(d.round),
              [&] { diagnoses.push_back(diagnosis_to_json(d)); });
    Json curricula = Json::array();
    for (const auto& c : store_.curricula_of_session(id))
      convert(where + "curriculum of round " + std::to_string(c.round),
              [&] { curricula.push_back(curriculum_to_json(c)); });
    out_.trials += trials.size();
    session["trials"] = std::move(trials);
    session["diagnoses"] = std::move(diagnoses);
    session["curricula"] = std::move(curricula);
    return session;
  }

 private:
  template <typename Fn>
  void convert(const std::string& what, Fn&& fn) {
    try {
      fn();
    } catch (const InputError& e) {
      out_.problems.push_back(store_.database_path().string() + ": " + what + " left out: " + e.what());
    }
  }

  const RecordStore& store_;
  RecordsExport& out_;
};

}  // namespace

RecordsExport export_records(const RecordStore& store) {
  RecordsExport out;
  SessionExporter exporter(store, out);
  Json learners = Json::array();
  for (const auto& learner : store.list_learners()) {
    Json sessions = Json::array();
    for (const auto& summary : learner.sessions) sessions.push_back(exporter.session(summary));
    learners.push_back({{"name", learner.name}, {"created", learner.created}, {"sessions", std::move(sessions)}});
  }
  Json studies = Json::array();
  for (const auto& study : store.list_studies()) {
    Json participants = Json::array();
    for (const auto& p : store.study_participants(study.name))
      participants.push_back(
          {{"learner", p.learner}, {"seq", p.seq}, {"condition", p.condition}, {"enrolled", p.enrolled}});
    studies.push_back({{"name", study.name},
                       {"task", study.task},
                       {"conditions", study.conditions},
                       {"target_per_condition", study.target_per_condition},
                       {"seed", study.seed},
                       {"created", study.created},
                       {"participants", std::move(participants)}});
  }
  out.doc = {{"format", kExportFormat},
             {"version", kExportVersion},
             {"schema_version", store.schema_version()},
             {"learners", std::move(learners)},
             {"studies", std::move(studies)}};
  return out;
}

namespace {

// `--out` naming the database or one of its companion files would replace the learner's records by the
// export: refused before anything is written.
void refuse_database_as_output(const RecordStore& store, const std::filesystem::path& out) {
  const auto& db = store.database_path();
  for (const auto& file : {db, std::filesystem::path(db.string() + "-wal"), std::filesystem::path(db.string() + "-shm"),
                           store.spill_path()}) {
    std::error_code ec, out_ec, file_ec;  // the files may not exist: then compare the resolved names
    const auto out_name = std::filesystem::weakly_canonical(out, out_ec);
    const auto file_name = std::filesystem::weakly_canonical(file, file_ec);
    const bool same = std::filesystem::equivalent(out, file, ec) || (!out_ec && !file_ec && out_name == file_name);
    if (same)
      throw InputError(out.string(), "is the learner database's own file " + file.string() + "; choose another --out");
  }
}

}  // namespace

RecordsExport export_database(const std::filesystem::path& data_dir, const std::filesystem::path& out) {
  return export_store(LearnerStore(data_dir, StoreOptions{.read_only = true}), out);
}

RecordsExport export_store(const RecordStore& store, const std::filesystem::path& out) {
  refuse_database_as_output(store, out);
  RecordsExport result = export_records(store);
  write_json_file(out, result.doc, 1);
  return result;
}

}  // namespace sc::records
