#pragma once
// The diagnosis page's pictures of each skill row: the skill as the expert does it and, when the page shows the
// pre-test's diagnosis, where the learner's pre-test went wrong (the trial of the skill's largest penalty, the part
// aligned with the expert's segment in orange). Each is small beside its bar, so pointing at one shows it four
// times as large with what it shows in words.
// Why a cache: reading the trial documents (and re-simulating parking paths) for every picture every frame cost
// the writing page more than a frame's time (docs/rendering.md). The pictures' points are read once per session,
// round and diagnosis shown.
#include <imgui.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/screens/learn_skill_picture.hpp"
#include "teaching/sessions/training_session.hpp"

namespace sc {

class DiagnosisRowPictures {
 public:
  // `placed`: the pre-test's places when the page shows that diagnosis, else null (no "where" pictures).
  void draw_row(ImDrawList& draw_list, ImVec2 size, const TrainingSession& session, const PlacedDiagnosis* placed,
                int skill, bool drilled, float scale);

 private:
  struct Row {
    std::optional<SkillPictureData> example;
    std::optional<TrialPartPictureData> place;
    int place_trial = 0;  // 0-based pre-test trial of `place`
    TargetReason reason = TargetReason::NoMistake;
  };
  const Row& row(const TrainingSession& session, const PlacedDiagnosis* placed, int skill);

  const TrainingSession* session_ = nullptr;
  int round_ = -1;
  std::vector<double> expertise_;  // the diagnosis the rows were read for
  bool placed_ = false;
  std::map<int, Row> rows_;
};

// What a "where" picture shows, by why the skill was charged there (pre-test trial `trial`, 1-based).
std::string place_caption(int trial, const std::string& skill, TargetReason reason);

}  // namespace sc
