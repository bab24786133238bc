#include "teaching/records/record_validation.hpp"

#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"

namespace sc::records {
namespace {

void require_json(const std::string& text, std::string_view what) {
  if (!Json::accept(text)) throw InputError("learner record", std::string(what) + " is not valid JSON");
}

}  // namespace

void require_text(std::string_view value, std::string_view what) {
  if (value.empty()) throw InputError("learner record", std::string(what) + " is empty");
}

// Tabs and newlines count as blank (the schema's CHECK on spaces alone lets them through).
void require_learner_name(std::string_view name) {
  const std::string what = "learner name";
  require_text(name, what);
  if (name.find_first_not_of(" \t\n\r\v\f") == std::string_view::npos)
    throw InputError("learner record", what + " is blank");
  for (unsigned char c : name)
    if (c < 0x20 || c == 0x7f) throw InputError("learner record", what + " contains a control character");
}

void validate_new_session(const NewSession& session) {
  require_learner_name(session.learner);
  require_text(session.task, "task");
  require_text(session.condition, "condition");
  require_text(session.started, "session start time");
  require_json(session.settings_json, "session settings");
}

void validate_trial(const TrialRecord& trial) {
  require_text(trial.task, "trial task");
  require_text(trial.device, "trial device");
  require_text(trial.started, "trial start time");
  require_text(trial.finished, "trial end time");
  require_json(trial.scenario_json, "trial scenario");
  require_json(trial.trajectory_json, "trial trajectory");
  if (trial.score && !std::isfinite(*trial.score)) throw InputError("learner record", "trial score is not finite");
  if (trial.round < 1) throw InputError("learner record", "trial round must be 1 or more");
}

void validate_diagnosis(const DiagnosisRecord& diagnosis) {
  require_json(diagnosis.expertise_json, "diagnosis expertise");
  require_json(diagnosis.targets_json, "diagnosis targets");
  require_text(diagnosis.extractor, "diagnosis extractor");
  require_text(diagnosis.created, "diagnosis time");
}

void validate_curriculum(const CurriculumRecord& curriculum) {
  require_text(curriculum.condition, "curriculum condition");
  require_json(curriculum.items_json, "curriculum items");
  require_text(curriculum.created, "curriculum time");
  for (const auto& drill : curriculum.drills) {
    require_json(drill.skills_json, "drill skills");
    require_json(drill.content_json, "drill content");
  }
}

void validate_progress(const SessionProgress& progress) {
  if (progress.round < 1 || progress.item_index < 0) throw InputError("learner record", "invalid session progress");
}

int last_seq_with_pending(const std::deque<PendingWrite>& pending, std::int64_t session_id, int stored_last) {
  int last = stored_last;
  for (const auto& write : pending) {
    if (const auto* trial = std::get_if<TrialWrite>(&write); trial && trial->trial.session_id == session_id)
      last = std::max(last, trial->seq);
  }
  return last;
}

bool apply_pending_to_resume(ResumePoint& point, const std::deque<PendingWrite>& pending) {
  bool finished = false;
  for (const auto& write : pending) {
    if (session_of(write) != point.session.id) continue;
    if (const auto* trial = std::get_if<TrialWrite>(&write)) {
      ++point.trials_done;
      if (trial->trial.progress_after) point.session.progress = *trial->trial.progress_after;
    } else if (const auto* progress = std::get_if<ProgressWrite>(&write)) {
      point.session.progress = progress->progress;
    } else if (std::holds_alternative<FinishWrite>(write)) {
      finished = true;
    }
  }
  return finished;
}

}  // namespace sc::records
