#pragma once
// What the Review screens show, loaded on demand from the learner database (opened read-only, so the
// review can run while the trainer writes): the session rows and their sort, the selected session's review
// (SessionReview with its task kit), the selected trial with its picture and playback, the before/after
// groups and the expertise/diagnosis of the session. Errors become a one-line message to show.
#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/core/review_pictures.hpp"
#include "app/gui/app_services.hpp"
#include "app/gui/screens/learn_skill_picture.hpp"
#include "teaching/review/diagnosis_explained.hpp"
#include "teaching/review/review_playback.hpp"
#include "teaching/review/session_filter.hpp"
#include "teaching/review/session_rows.hpp"
#include "teaching/tasks/task_kit_cache.hpp"

namespace sc {

class ReviewModel {
 public:
  // Headless (screenshots): a deterministic database is made first by the trainer's scripted learner.
  explicit ReviewModel(AppServices& services);

  std::string message;  // last problem, one line; empty if none

  // The session list's filter as typed (ImGui text buffers); filter() reads it as a review::SessionFilter.
  struct FilterFields {
    std::array<char, 64> learner{}, from{}, to{};
    int task = 0;  // 0 every task, 1 parking, 2 writing
  };
  FilterFields filter_fields;
  review::SessionFilter filter() const;

  const std::vector<review::SessionListRow>& rows() const { return rows_; }
  void sort(review::SessionColumn column, bool ascending);
  void reload();

  // Selection. select_session loads the session (and its task's kit) and selects its first trial.
  void select_session(std::int64_t id);
  const review::SessionReview* session() const { return session_.get(); }
  const review::SessionListRow* session_row() const;
  void select_trial(int seq);
  const review::TrialReview* trial() const { return trial_ ? &*trial_ : nullptr; }
  review_view::TrialPicture& picture() { return picture_; }
  // The selected session's skill colours (session_palette), for every picture and swatch of the Review.
  const review_view::SkillPalette& palette() const { return palette_; }
  review::Playback& playback() { return playback_; }

  // Of the selected session, computed on first use.
  const std::vector<review::BeforeAfterGroup>& before_after_groups();
  const review_view::BeforeAfterPicture& before_after_picture(std::size_t group);
  std::vector<std::string> before_after_lines(std::size_t group);
  const review_view::ExpertiseChart* expertise_chart();
  const review::DiagnosisExplanation* diagnosis();
  std::string diagnosis_problem;
  // The picture of `skill` as the expert does it (its longest segment in the session's pool), read once; null when
  // the pool has none.
  const SkillPictureData* skill_picture(int skill);
  // The picture of where a target of diagnosis() went wrong (its SkillPlace), read once; null without one.
  const TrialPartPictureData* place_picture(int skill);
  // One line per round: practice planned and played against the budget (review::practice_round_text).
  const std::vector<std::string>& practice_lines();

 private:
  const std::vector<review::TrialReview>& test_trials();

  AppServices& services_;
  std::unique_ptr<records::RecordStore> store_;
  std::vector<review::SessionListRow> rows_;
  TaskKitCache kits_;
  std::unique_ptr<review::SessionReview> session_;
  std::optional<review::TrialReview> trial_;
  review_view::TrialPicture picture_;
  review_view::SkillPalette palette_;
  review::Playback playback_;
  std::optional<std::vector<review::BeforeAfterGroup>> groups_;
  std::optional<std::vector<review::TrialReview>> test_trials_;
  std::map<std::size_t, review_view::BeforeAfterPicture> group_pictures_;
  std::optional<review::ExpertiseRounds> rounds_;  // read once per session: the chart and the palette
  std::string rounds_problem_;                     // why rounds_ is empty, shown when the chart is asked for
  std::optional<review_view::ExpertiseChart> chart_;
  std::optional<review::DiagnosisExplanation> diagnosis_;
  bool diagnosis_tried_ = false;
  std::map<int, TrialPartPictureData> place_pictures_;
  std::map<int, std::optional<SkillPictureData>> skill_pictures_;
  std::optional<std::vector<std::string>> practice_lines_;
};

}  // namespace sc
