#pragma once
// One trial as the instructor inspects it: the learner's path, the expert's trial for the same scenario,
// the SkillExtractor's segmentation of both (skill ids with the kit's plain words), for practice and demo
// trials the drill's ghost path with its planned skills, and the reward over time.
//
// SessionReview reads a session once (SessionRecord) and answers the review's questions for it, caching
// what is costly to recompute (expert trials of evaluation scenarios are re-planned; drills re-projected).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/core/task_kind.hpp"
#include "teaching/review/review_tracks.hpp"
#include "teaching/review/session_record.hpp"
#include "teaching/sessions/task_kit.hpp"

namespace sc::review {

struct SkillSpan {
  int skill = 0;
  int begin = 0;  // step index, as in SkillSegment
  int end = 0;
  std::string description;  // kit.describe_skill(skill)
};

struct TrialReview {
  records::StoredTrial stored;  // kind, round, drill index, score, device, times
  TaskKind task = TaskKind::parking;
  Json learner;  // the trial document as stored
  TrialTrack learner_track;
  std::vector<SkillSpan> learner_skills;  // the extractor on the learner's steps
  std::optional<Json> expert;             // pre-test/eval: the expert's trial for the same scenario
  TrialTrack expert_track;
  std::vector<SkillSpan> expert_skills;
  std::optional<Json> ghost;  // demo/practice: the drill the learner saw as a ghost
  TrialTrack ghost_track;
  std::vector<SkillSpan> ghost_skills;  // the drill plan's skills (what the drill was built to train)
  // Reward (<= 0, 0 best) over the trial: parking, the reward after each control step; writing, the score
  // of the ink written so far at evenly spaced points. Sample i is at time reward_times[i] seconds.
  std::vector<double> rewards;
  std::vector<double> reward_times;
  double reward = 0.0;  // the kit's reward of the whole trial (the stored score when present)
  std::string label;    // "pre-test 2 (round 1)", "practice of drill 1 (round 1)", ...
};

class SessionReview {
 public:
  SessionReview(const TaskKit& kit, SessionRecord record);

  const SessionRecord& record() const { return record_; }
  const TaskKit& kit() const { return kit_; }
  // Throws InputError for an unknown seq, a trial of another task or a document the kit cannot read.
  TrialReview trial(int seq) const;
  // The expert's trial for a scenario (pool lookup, otherwise re-planned once and cached).
  const Json& expert_for(const Json& scenario) const;
  // The drill played in `round` as item `index` (from the stored curriculum), projected once and cached;
  // nullptr when the session has no such drill.
  const PlayableDrill* drill(int round, int index) const;

 private:
  const TaskKit& kit_;
  SessionRecord record_;
  mutable std::map<std::string, Json> experts_;
  mutable std::map<std::pair<int, int>, std::optional<PlayableDrill>> drills_;
};

std::vector<SkillSpan> skill_spans(const TaskKit& kit, const Segmentation& segmentation);
std::string trial_label(const records::StoredTrial& trial);

}  // namespace sc::review
