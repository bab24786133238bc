#include "teaching/review/trial_review.hpp"

#include <algorithm>

#include "engine/core/error.hpp"
#include "engine/parking/parking_replay.hpp"
#include "teaching/drills/drill_plan_json.hpp"

namespace sc::review {
namespace {

Json parse_stored(const std::string& text, const std::string& where) {
  try {
    return Json::parse(text);
  } catch (const Json::exception& e) {
    throw InputError(where, std::string("is not JSON: ") + e.what());
  }
}

// Parking: the replay gives the exact end state and every control step's reward.
void parking_rewards(TrialReview& review, const StepSequence& steps, const std::string& where) {
  const ParkingReplay replay = replay_parking_trial(parse_parking_trial(review.learner, where));
  std::optional<VehicleState> end;
  if (static_cast<int>(replay.steps.size()) == steps.length() && !replay.steps.empty())
    end = replay.steps.back().vehicle;
  review.learner_track = track_of(TaskKind::parking, steps, end);
  for (const auto& step : replay.steps) {
    review.rewards.push_back(step.reward);
    review.reward_times.push_back(step.t / static_cast<double>(parking::kControlHz));
  }
}

// Writing has no per-step reward: score the ink written up to evenly spaced points instead.
void writing_rewards(TrialReview& review, const TaskKit& kit, const PlayableDrill* drill) {
  const Json& points = review.learner.at("points");
  const std::size_t n = points.size();
  const int samples = static_cast<int>(std::min<std::size_t>(n, 24));
  const double seconds = review.learner_track.step_seconds * review.learner_track.steps();
  for (int i = 1; i <= samples; ++i) {
    const std::size_t keep =
        std::max<std::size_t>(2, n * static_cast<std::size_t>(i) / static_cast<std::size_t>(samples));
    Json prefix = review.learner;
    prefix["points"] = Json(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(std::min(keep, n)));
    if (prefix.contains("t") && prefix["t"].is_array() && prefix["t"].size() == n)
      prefix["t"] = Json(review.learner["t"].begin(),
                         review.learner["t"].begin() + static_cast<std::ptrdiff_t>(std::min(keep, n)));
    review.rewards.push_back(drill ? kit.drill_attempt_reward(*drill, prefix) : kit.reward_of(prefix));
    review.reward_times.push_back(seconds * static_cast<double>(i) / samples);
  }
}

}  // namespace

std::vector<SkillSpan> skill_spans(const TaskKit& kit, const Segmentation& segmentation) {
  std::vector<SkillSpan> spans;
  for (const SkillSegment& s : segmentation.segments)
    spans.push_back({s.skill, s.begin, s.end, kit.describe_skill(s.skill)});
  return spans;
}

std::string trial_label(const records::StoredTrial& trial) {
  const auto& r = trial.record;
  const std::string round = " (round " + std::to_string(r.round) + ")";
  const std::string drill = r.drill_index ? " of drill " + std::to_string(*r.drill_index + 1) : "";
  switch (r.kind) {
    case records::TrialKind::Pretest:
      return "pre-test, trial " + std::to_string(trial.seq) + round;
    case records::TrialKind::Eval:
      return "evaluation, trial " + std::to_string(trial.seq) + round;
    case records::TrialKind::Practice:
      return "practice" + drill + ", trial " + std::to_string(trial.seq) + round;
    case records::TrialKind::Demo:
      return "demo" + drill + ", trial " + std::to_string(trial.seq) + round;
  }
  return "trial " + std::to_string(trial.seq);
}

SessionReview::SessionReview(const TaskKit& kit, SessionRecord record) : kit_(kit), record_(std::move(record)) {
  if (record_.session.task != kit_.task())
    throw InputError("session " + std::to_string(record_.session.id),
                     "is a " + record_.session.task + " session, reviewed with the " + kit_.task() + " kit");
}

const Json& SessionReview::expert_for(const Json& scenario) const {
  const std::string key = scenario.dump();
  auto it = experts_.find(key);
  if (it == experts_.end()) it = experts_.emplace(key, kit_.expert_trial(scenario)).first;
  return it->second;
}

const PlayableDrill* SessionReview::drill(int round, int index) const {
  const auto key = std::make_pair(round, index);
  auto it = drills_.find(key);
  if (it == drills_.end()) {
    std::optional<PlayableDrill> projected;
    if (const auto* curriculum = record_.curriculum(round))
      for (const auto& d : curriculum->drills)
        if (d.index == index) {
          const std::string where = "session " + std::to_string(record_.session.id) + " drill " + std::to_string(index);
          const Json content = parse_stored(d.content_json, where);
          const JsonView view(content, where);
          projected = kit_.projector().project(drill_plan_from_json(view.at("plan")));
        }
    it = drills_.emplace(key, std::move(projected)).first;
  }
  return it->second ? &*it->second : nullptr;
}

TrialReview SessionReview::trial(int seq) const {
  const records::StoredTrial& stored = record_.trial(seq);
  const std::string where = "session " + std::to_string(record_.session.id) + " trial " + std::to_string(seq);
  if (stored.record.task != kit_.task()) throw InputError(where, "is a " + stored.record.task + " trial");
  TrialReview review;
  review.stored = stored;
  review.task = parse_task_kind(stored.record.task, where);
  review.label = trial_label(stored);
  review.learner = parse_stored(stored.record.trajectory_json, where);
  const StepSequence steps = kit_.steps_of(review.learner);
  review.learner_skills = skill_spans(kit_, kit_.extractor().extract(steps));

  const PlayableDrill* drill = nullptr;
  const auto kind = stored.record.kind;
  if ((kind == records::TrialKind::Practice || kind == records::TrialKind::Demo) && stored.record.drill_index)
    drill = this->drill(stored.record.round, *stored.record.drill_index);
  if (drill) {
    review.ghost = kit_.drill_trial(*drill);
    review.ghost_track = ghost_track(review.task, drill->ghost_path, drill->steps);
    review.ghost_skills = skill_spans(kit_, plan_segmentation(drill->plan));
  } else {
    const Json scenario = parse_stored(stored.record.scenario_json, where + " scenario");
    review.expert = expert_for(scenario);
    const StepSequence expert_steps = kit_.steps_of(*review.expert);
    std::optional<VehicleState> end;
    if (review.task == TaskKind::parking) {
      const ParkingReplay replay = replay_parking_trial(parse_parking_trial(*review.expert, "expert trial"));
      if (static_cast<int>(replay.steps.size()) == expert_steps.length() && !replay.steps.empty())
        end = replay.steps.back().vehicle;
    }
    review.expert_track = track_of(review.task, expert_steps, end);
    review.expert_skills = skill_spans(kit_, kit_.extractor().extract(expert_steps));
  }

  if (review.task == TaskKind::parking) {
    parking_rewards(review, steps, where);
  } else {
    review.learner_track = track_of(review.task, steps, std::nullopt);
    // Demos and practice are measured against the drill (they do not write the whole word).
    writing_rewards(review, kit_, drill);
  }
  review.reward = stored.record.score ? *stored.record.score
                  : drill             ? kit_.drill_attempt_reward(*drill, review.learner)
                                      : kit_.reward_of(review.learner);
  return review;
}

}  // namespace sc::review
