#include "teaching/sessions/session_records.hpp"

#include "teaching/curricula/curriculum_json.hpp"
#include "teaching/drills/drill_plan_json.hpp"
#include "teaching/expertise/expertise_json.hpp"

namespace sc {

records::NewSession session_record(const SessionSettings& settings, const std::string& task,
                                   const std::string& started) {
  records::NewSession session;
  session.learner = settings.learner;
  session.task = task;
  session.condition = std::string(condition_key(settings.condition));
  session.seed = settings.seed;
  session.settings_json = settings_to_json(settings).dump();
  session.started = started;
  session.study = settings.study;
  return session;
}

records::DiagnosisRecord diagnosis_record(std::int64_t session_id, int round, const ExpertiseEstimate& diagnosis,
                                          const std::string& extractor, const std::string& created) {
  records::DiagnosisRecord record;
  record.session_id = session_id;
  record.round = round;
  record.expertise_json = expertise_to_json(diagnosis).dump();
  record.targets_json = Json(diagnosis.targets).dump();
  record.extractor = extractor;
  record.created = created;
  return record;
}

records::CurriculumRecord curriculum_record(std::int64_t session_id, int round, StudyCondition condition,
                                            const Curriculum& curriculum, const std::string& created) {
  records::CurriculumRecord record;
  record.session_id = session_id;
  record.round = round;
  record.condition = std::string(condition_key(condition));
  record.items_json = curriculum_to_json(curriculum).dump();
  for (std::size_t i = 0; i < curriculum.items.size(); ++i) {
    const PracticeItem& item = curriculum.items[i];
    record.drills.push_back(
        {static_cast<int>(i), Json(item.material.skills()).dump(),
         Json{{"plan", drill_plan_to_json(item.material)}, {"sessions", item.sessions}, {"steps", item.steps()}}
             .dump()});
  }
  record.created = created;
  return record;
}

records::TrialRecord trial_record(const TrialPlace& place, const std::string& task, const std::string& device,
                                  const Json& trial, std::optional<double> score) {
  records::TrialRecord record;
  record.session_id = place.session_id;
  record.kind = place.kind;
  record.round = place.round;
  record.drill_index = place.drill_index;
  record.task = task;
  record.scenario_json = trial.contains("scenario") ? trial.at("scenario").dump() : "{}";
  record.trajectory_json = trial.dump();
  record.score = score;
  record.device = device;
  return record;
}

}  // namespace sc
