#include "app/core/learn_scripted_learner.hpp"

#include <algorithm>
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/core/task_kind.hpp"
#include "engine/parking/parking_trial.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/tasks/writing_realistic_learner.hpp"

namespace sc {
namespace {

Json parking_attempt(const Json& reference, double skill, Rng& rng, const std::string& device) {
  ParkingTrial trial = parse_parking_trial(reference, "scripted learner's reference");
  for (ParkingAction& a : trial.actions) {
    a[0] = std::clamp(a[0] * skill, -1.0, 1.0);
    a[1] = std::clamp(a[1] + (1.0 - skill) * rng.uniform(-0.5, 0.5), -1.0, 1.0);
  }
  trial.states.clear();
  trial.rewards.clear();
  trial.success.reset();
  trial.source = "learner";
  trial.device = device;
  return parking_trial_to_json(trial);
}

Json writing_attempt(const Json& reference, double skill, Rng& rng, const std::string& device) {
  writing::WritingTrial trial = writing::parse_writing_trial(reference, "scripted learner's reference");
  const double error = (1.0 - skill) * 6.0;
  const double phase = rng.uniform(0.0, 6.283);
  for (std::size_t i = 0; i < trial.points.size(); ++i) {
    const double t = static_cast<double>(i) * 0.15 + phase;
    trial.points[i].x += error * (0.6 + std::sin(t));
    trial.points[i].y += error * std::cos(t * 0.7);
  }
  trial.score.reset();
  trial.source = "learner";
  trial.device = device;
  return writing::writing_trial_json(trial);
}

// The reference's word in drawer `hand`'s letters, at that drawer's size, moved onto the reference's first
// point (a learner tracing the guide starts where it does); time stamps, if any, spread over the same time.
Json in_hand(const Json& reference, int hand) {
  writing::WritingTrial trial = writing::parse_writing_trial(reference, "scripted learner's reference");
  if (trial.points.empty()) return reference;
  const ClassicDrawerGlyphs glyphs = ClassicDrawerGlyphs::load();
  const std::string& word = trial.scenario.word;
  const WrittenWord written = written_word(glyphs, word, std::vector<int>(word.size(), hand));
  const double dx = trial.points.front().x - written.points.front().x;
  const double dy = trial.points.front().y - written.points.front().y;
  const double duration = trial.times.size() > 1 ? trial.times.back() - trial.times.front() : 0.0;
  const double start = trial.times.empty() ? 0.0 : trial.times.front();
  trial.points.clear();
  for (const writing::TracePoint& p : written.points) trial.points.push_back({p.x + dx, p.y + dy, p.pen});
  if (!trial.times.empty()) {
    trial.times.clear();
    const double n = std::max<double>(1.0, static_cast<double>(trial.points.size() - 1));
    for (std::size_t i = 0; i < trial.points.size(); ++i) trial.times.push_back(start + duration * i / n);
  }
  return writing::writing_trial_json(trial);
}

}  // namespace

Json scripted_attempt(const Json& reference, double skill, std::uint64_t seed, const std::string& device, int hand) {
  const bool writing =
      parse_task_kind(reference.value("task", ""), "scripted learner's reference: $.task") == TaskKind::writing;
  return scripted_attempt(writing && hand > 0 ? in_hand(reference, hand) : reference, skill, seed, device);
}

Json scripted_attempt(const Json& reference, double skill, std::uint64_t seed, const std::string& device) {
  skill = std::clamp(skill, 0.0, 1.0);
  Rng rng(seed);
  const TaskKind task = parse_task_kind(reference.value("task", ""), "scripted learner's reference: $.task");
  if (task == TaskKind::parking) return parking_attempt(reference, skill, rng, device);
  return writing_attempt(reference, skill, rng, device);
}

}  // namespace sc

namespace sc {
namespace {

std::uint64_t attempt_seed(const TrainingSession& s, int kind, int index) {
  return Rng(s.settings().seed).fork(static_cast<std::uint64_t>(s.round() * 1000 + kind * 100 + index)).next_u64();
}

}  // namespace

void play_scripted_round(TrainingSession& s, const ScriptedRunHooks& hooks) {
  const std::string device = s.settings().device;
  int practice_done = 0;
  while (s.phase() != SessionPhase::Summary && !(hooks.stop && hooks.stop(s))) {
    switch (s.phase()) {
      case SessionPhase::Pretest:
      case SessionPhase::Evaluation: {
        const bool pre = s.phase() == SessionPhase::Pretest;
        const Json attempt = scripted_attempt(s.test_expert_trial(), pre ? hooks.skills.pretest : hooks.skills.eval,
                                              attempt_seed(s, pre ? 0 : 3, s.item_index()), device, hooks.hand);
        const SubmittedTrial kept = s.submit_test_trial(attempt, {});
        if (hooks.after_trial) hooks.after_trial(s, pre ? "pretest" : "eval", kept);
        break;
      }
      case SessionPhase::Diagnosis:
        s.analyse();
        if (hooks.after_analysis) hooks.after_analysis(s);
        break;
      case SessionPhase::Drills: {
        const int item = s.current_item();
        const Json reference = s.kit().drill_trial(s.drill(item));
        s.record_demo(item, reference, {});
        const double skill = std::min(hooks.skills.practice_end, hooks.skills.practice_start + 0.05 * practice_done);
        const SubmittedTrial kept =
            s.submit_practice(scripted_attempt(reference, skill, attempt_seed(s, 2, s.item_index()), device), {});
        ++practice_done;
        if (hooks.after_trial) hooks.after_trial(s, "practice", kept);
        break;
      }
      case SessionPhase::Summary:
        break;
    }
  }
}

}  // namespace sc
