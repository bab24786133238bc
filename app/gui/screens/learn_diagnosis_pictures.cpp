#include "app/gui/screens/learn_diagnosis_pictures.hpp"

namespace sc {

std::string place_caption(int trial, const std::string& skill, TargetReason reason) {
  const std::string lead = "Your pre-test trial " + std::to_string(trial) + " in yellow, over the expert's in blue. ";
  if (reason == TargetReason::Missing)
    return lead + "The skill model did not find \"" + skill +
           "\" in it; in orange, the part of yours that lines up with where the expert does it.";
  if (reason == TargetReason::RepeatedError)
    return lead + "In orange, the part of yours that lines up with where the expert does \"" + skill +
           "\": a little off here, and in every other trial too.";
  return lead + "In orange, the part of yours that lines up with where the expert does \"" + skill +
         "\": done clearly worse than the rest of your trials.";
}

const DiagnosisRowPictures::Row& DiagnosisRowPictures::row(const TrainingSession& s, const PlacedDiagnosis* placed,
                                                           int skill) {
  if (session_ != &s || round_ != s.round() || expertise_ != s.diagnosis().expertise ||
      placed_ != (placed != nullptr)) {
    session_ = &s;
    round_ = s.round();
    expertise_ = s.diagnosis().expertise;
    placed_ = placed != nullptr;
    rows_.clear();
  }
  if (const auto found = rows_.find(skill); found != rows_.end()) return found->second;
  Row r;
  const auto& pool = s.kit().expert_pool();
  r.example = skill_example_picture(pool, skill);
  if (const TargetWhy* why = placed ? charged_why(*placed, skill) : nullptr) {
    const auto trial = static_cast<std::size_t>(why->trial);
    const ExpertDemo& expert = pool.at(static_cast<std::size_t>(s.pretest_pool_indices().at(trial)));
    r.place = trial_part_picture_data(s.pretest_trials().at(trial), expert.trial, why->learner_begin, why->learner_end,
                                      placed->learner_steps.at(trial));
    r.place_trial = why->trial;
    r.reason = why->reason;
  }
  return rows_.emplace(skill, std::move(r)).first->second;
}

void DiagnosisRowPictures::draw_row(ImDrawList& d, ImVec2 pic, const TrainingSession& s, const PlacedDiagnosis* placed,
                                    int skill, bool drilled, float sc) {
  const Row& r = row(s, placed, skill);
  const std::string words = s.kit().describe_skill(skill);
  const auto draw_example = [&](ImDrawList& list, ImVec2 at, ImVec2 size) {
    if (r.example) draw_skill_picture(list, at, size, *r.example, drilled);
  };
  draw_example(d, ImGui::GetCursorScreenPos(), pic);
  ImGui::Dummy(pic);
  if (r.example)
    enlarge_on_hover("How the expert does \"" + words +
                         "\": the coloured part, ending at the dot; in grey, the rest of the expert's trial",
                     pic, draw_example);
  if (!placed) return;
  ImGui::SameLine(0, 6 * sc);
  const std::string label = "trial " + std::to_string(r.place_trial + 1);
  const auto draw_where = [&](ImDrawList& list, ImVec2 at, ImVec2 size) {
    if (r.place) draw_trial_part_picture(list, at, size, *r.place, label.c_str());
  };
  draw_where(d, ImGui::GetCursorScreenPos(), pic);
  ImGui::Dummy(pic);
  if (r.place) enlarge_on_hover(place_caption(r.place_trial + 1, words, r.reason), pic, draw_where);
}

}  // namespace sc
