#pragma once
// What a training session writes to the learner store, as records (docs/database.md): the session row, a
// round's diagnosis and curriculum, and a trial. Pure mappings, so the session's phase machine
// (training_session.hpp) holds no record layout and the layout has one place.
#include <cstdint>
#include <optional>
#include <string>

#include "engine/core/json_file.hpp"
#include "teaching/curricula/curriculum.hpp"
#include "teaching/expertise/expertise_estimation.hpp"
#include "teaching/records/record_types.hpp"
#include "teaching/sessions/session_settings.hpp"

namespace sc {

records::NewSession session_record(const SessionSettings& settings, const std::string& task,
                                   const std::string& started);

// Alg. 2's estimate and its targets, with the extractor's name.
records::DiagnosisRecord diagnosis_record(std::int64_t session_id, int round, const ExpertiseEstimate& diagnosis,
                                          const std::string& extractor, const std::string& created);

// The curriculum as played (items_json) and one drill row per item (its skills, plan, sessions, steps).
records::CurriculumRecord curriculum_record(std::int64_t session_id, int round, StudyCondition condition,
                                            const Curriculum& curriculum, const std::string& created);

// One trial document: its scenario (or {} when it has none) and the whole document.
struct TrialPlace {
  std::int64_t session_id = 0;
  records::TrialKind kind = records::TrialKind::Pretest;
  int round = 1;
  std::optional<int> drill_index;  // demo/practice: the curriculum item
};
records::TrialRecord trial_record(const TrialPlace& place, const std::string& task, const std::string& device,
                                  const Json& trial, std::optional<double> score);

}  // namespace sc
