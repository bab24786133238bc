#include "teaching/records/record_json.hpp"

namespace sc::records {
namespace {

std::string payload_text(const JsonView& node) { return node.raw().dump(); }

int small_int(const JsonView& node) {
  const auto value = node.integer();
  if (value < 0 || value > 1'000'000'000) node.fail("value " + std::to_string(value) + " is out of range");
  return static_cast<int>(value);
}

std::string optional_string(const JsonView& node, std::string_view key) {
  auto member = node.find(key);
  return member ? member->string() : std::string();
}

}  // namespace

Json payload(const std::string& text) { return parse_json_text(text, "stored JSON"); }

Json progress_to_json(const SessionProgress& progress) {
  return {{"round", progress.round}, {"phase", to_string(progress.phase)}, {"item_index", progress.item_index}};
}

SessionProgress progress_from_json(const JsonView& node) {
  SessionProgress progress;
  progress.round = small_int(node.at("round"));
  auto phase = node.at("phase");
  progress.phase = session_phase_from_string(phase.string(), phase.path());
  progress.item_index = small_int(node.at("item_index"));
  return progress;
}

Json trial_to_json(const TrialRecord& trial, int seq) {
  Json out = {{"session_id", trial.session_id},
              {"seq", seq},
              {"kind", to_string(trial.kind)},
              {"round", trial.round},
              {"drill_index", trial.drill_index ? Json(*trial.drill_index) : Json(nullptr)},
              {"task", trial.task},
              {"score", trial.score ? Json(*trial.score) : Json(nullptr)},
              {"device", trial.device},
              {"started", trial.started},
              {"finished", trial.finished},
              {"scenario", payload(trial.scenario_json)},
              {"trajectory", payload(trial.trajectory_json)}};
  if (trial.progress_after) out["progress_after"] = progress_to_json(*trial.progress_after);
  return out;
}

TrialRecord trial_from_json(const JsonView& node) {
  TrialRecord trial;
  trial.session_id = node.at("session_id").integer();
  auto kind = node.at("kind");
  trial.kind = trial_kind_from_string(kind.string(), kind.path());
  trial.round = small_int(node.at("round"));
  if (auto drill = node.find("drill_index")) trial.drill_index = small_int(*drill);
  trial.task = node.at("task").string();
  if (auto score = node.find("score")) trial.score = score->number();
  trial.device = node.at("device").string();
  trial.started = node.at("started").string();
  trial.finished = node.at("finished").string();
  trial.scenario_json = payload_text(node.at("scenario"));
  trial.trajectory_json = payload_text(node.at("trajectory"));
  if (auto progress = node.find("progress_after")) trial.progress_after = progress_from_json(*progress);
  return trial;
}

int trial_seq_from_json(const JsonView& node) { return small_int(node.at("seq")); }

Json diagnosis_to_json(const DiagnosisRecord& diagnosis) {
  return {{"session_id", diagnosis.session_id},
          {"round", diagnosis.round},
          {"expertise", payload(diagnosis.expertise_json)},
          {"targets", payload(diagnosis.targets_json)},
          {"extractor", diagnosis.extractor},
          {"model_id", diagnosis.model_id},
          {"created", diagnosis.created}};
}

DiagnosisRecord diagnosis_from_json(const JsonView& node) {
  DiagnosisRecord diagnosis;
  diagnosis.session_id = node.at("session_id").integer();
  diagnosis.round = small_int(node.at("round"));
  diagnosis.expertise_json = payload_text(node.at("expertise"));
  diagnosis.targets_json = payload_text(node.at("targets"));
  diagnosis.extractor = node.at("extractor").string();
  diagnosis.model_id = optional_string(node, "model_id");
  diagnosis.created = node.at("created").string();
  return diagnosis;
}

Json curriculum_to_json(const CurriculumRecord& curriculum) {
  Json drills = Json::array();
  for (const auto& drill : curriculum.drills) {
    drills.push_back(
        {{"index", drill.index}, {"skills", payload(drill.skills_json)}, {"content", payload(drill.content_json)}});
  }
  return {{"session_id", curriculum.session_id},     {"round", curriculum.round},   {"condition", curriculum.condition},
          {"items", payload(curriculum.items_json)}, {"drills", std::move(drills)}, {"created", curriculum.created}};
}

CurriculumRecord curriculum_from_json(const JsonView& node) {
  CurriculumRecord curriculum;
  curriculum.session_id = node.at("session_id").integer();
  curriculum.round = small_int(node.at("round"));
  curriculum.condition = node.at("condition").string();
  curriculum.items_json = payload_text(node.at("items"));
  curriculum.created = node.at("created").string();
  auto drills = node.at("drills");
  for (std::size_t i = 0; i < drills.size(); ++i) {
    auto drill = drills.at(i);
    curriculum.drills.push_back(
        {small_int(drill.at("index")), payload_text(drill.at("skills")), payload_text(drill.at("content"))});
  }
  return curriculum;
}

Json session_to_json(const SessionRow& session) {
  return {{"id", session.id},
          {"learner", session.learner},
          {"task", session.task},
          {"condition", session.condition},
          {"seed", session.seed},
          {"settings", payload(session.settings_json)},
          {"started", session.started},
          {"finished", session.finished ? Json(*session.finished) : Json(nullptr)},
          {"progress", progress_to_json(session.progress)},
          {"study", session.study.empty() ? Json(nullptr) : Json(session.study)}};
}

}  // namespace sc::records
