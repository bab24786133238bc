#include "teaching/records/records_import.hpp"

#include <set>
#include <tuple>

#include "engine/core/error.hpp"
#include "teaching/records/record_json.hpp"
#include "teaching/records/records_export.hpp"

namespace sc::records {
namespace {

class Importer {
 public:
  explicit Importer(RecordStore& store) : store_(store) {
    for (const auto& l : store_.list_learners()) {
      learners_.insert(l.name);
      for (const auto& s : l.sessions) sessions_.insert({l.name, s.session.task, s.session.started});
    }
  }

  // A study is created whole, with every participant's place, so one the store holds is refused.
  void refuse_study_overlap(const JsonView& doc) const {
    std::set<std::string, std::less<>> studies;
    for (const auto& s : store_.list_studies()) studies.insert(s.name);
    const auto list = doc.at("studies");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const auto name = list.at(i).at("name").string();
      if (studies.count(name) != 0)
        throw InputError(where(), "already holds the study \"" + name + "\"; import into a store without it");
    }
  }

  void study(const JsonView& node) {
    StudyDefinition study{node.at("name").string(),
                          node.at("task").string(),
                          {},
                          static_cast<int>(node.at("target_per_condition").integer()),
                          node.at("seed").raw().get<std::uint64_t>(),
                          node.at("created").string()};
    const auto conditions = node.at("conditions");
    for (std::size_t i = 0; i < conditions.size(); ++i) study.conditions.push_back(conditions.at(i).string());
    store_.create_study(study);
    const auto participants = node.at("participants");
    for (std::size_t i = 0; i < participants.size(); ++i) {
      const auto p = participants.at(i);
      const auto placed = store_.enrol(study.name, p.at("learner").string(), p.at("enrolled").string());
      if (placed.seq != p.at("seq").integer() || placed.condition != p.at("condition").string())
        p.fail("the store assigned place " + std::to_string(placed.seq) + " (" + placed.condition + ") instead");
    }
    ++result_.studies;
  }

  void session(const JsonView& node) {
    // Already here (an earlier import of the same records): the learner, task and start time name a session.
    if (!sessions_.insert({node.at("learner").string(), node.at("task").string(), node.at("started").string()})
             .second) {
      ++result_.sessions_already_there;
      return;
    }
    NewSession s{node.at("learner").string(),
                 node.at("task").string(),
                 node.at("condition").string(),
                 node.at("seed").raw().get<std::uint64_t>(),
                 node.at("settings").raw().dump(),
                 node.at("started").string(),
                 ""};
    if (const auto study = node.find("study")) s.study = study->string();
    const auto id = store_.begin_session(s);
    const auto trials = node.at("trials");
    for (std::size_t i = 0; i < trials.size(); ++i) {
      auto trial = trial_from_json(trials.at(i));
      if (trial_seq_from_json(trials.at(i)) != static_cast<int>(i) + 1)
        trials.at(i).fail("trials are not numbered 1, 2, ...");
      trial.session_id = id;
      trial.progress_after.reset();
      kept(store_.record_trial(trial));
    }
    for_each(node.at("diagnoses"), [&](const JsonView& d) {
      auto diagnosis = diagnosis_from_json(d);
      diagnosis.session_id = id;
      kept(store_.save_diagnosis(diagnosis));
    });
    for_each(node.at("curricula"), [&](const JsonView& c) {
      auto curriculum = curriculum_from_json(c);
      curriculum.session_id = id;
      kept(store_.save_curriculum(curriculum));
    });
    kept(store_.save_progress(id, progress_from_json(node.at("progress"))));
    if (const auto finished = node.find("finished")) kept(store_.finish_session(id, finished->string()));
    ++result_.sessions;
    result_.trials += trials.size();
  }

  void learner(const JsonView& node) {
    const std::string name = node.at("name").string();
    if (!learners_.insert(name).second) return;  // their sessions are added to theirs
    store_.ensure_learner(name, node.at("created").string());
    ++result_.learners;
  }

  const RecordsImport& result() const { return result_; }

 private:
  template <typename Fn>
  static void for_each(const JsonView& list, Fn&& fn) {
    for (std::size_t i = 0; i < list.size(); ++i) fn(list.at(i));
  }
  std::string where() const { return store_.database_path().string(); }
  // The import stops at the first record the store cannot keep now: what is pending is in its spill file.
  void kept(const SaveResult& result) const {
    if (!result.stored) throw InputError(where(), "import stopped: " + result.message);
  }

  RecordStore& store_;
  RecordsImport result_;
  std::set<std::string, std::less<>> learners_;
  std::set<std::tuple<std::string, std::string, std::string>> sessions_;  // learner, task, started
};

}  // namespace

RecordsImport import_records(const Json& doc, const std::string& source, RecordStore& store) {
  const JsonView root(doc, source);
  if (root.at("format").string() != kExportFormat || root.at("version").integer() != kExportVersion)
    throw InputError(source, "is not a skillcoach-records export of version " + std::to_string(kExportVersion));
  Importer importer(store);
  importer.refuse_study_overlap(root);
  const auto learners = root.at("learners");
  for (std::size_t i = 0; i < learners.size(); ++i) importer.learner(learners.at(i));
  const auto studies = root.at("studies");
  for (std::size_t i = 0; i < studies.size(); ++i) importer.study(studies.at(i));
  for (std::size_t i = 0; i < learners.size(); ++i) {
    const auto sessions = learners.at(i).at("sessions");
    for (std::size_t j = 0; j < sessions.size(); ++j) importer.session(sessions.at(j));
  }
  return importer.result();
}

}  // namespace sc::records
