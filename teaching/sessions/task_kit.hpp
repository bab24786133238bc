#pragma once
// TaskKit: everything the teaching flow needs to know about one task (parking or writing), so that the
// training session, the diagnose command, the synthetic students and the app screens stay task-agnostic.
// Implementations: teaching/tasks/parking_kit.hpp and teaching/tasks/writing_kit.hpp.
//
// Trials travel as trajectory-file documents (docs/trajectory-format.md): {"task", "scenario", ...}.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/curricula/curriculum.hpp"
#include "teaching/drills/drill_plan.hpp"
#include "teaching/expertise/execution_expertise.hpp"
#include "teaching/expertise/execution_reference.hpp"
#include "teaching/expertise/trace_alignment.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

// One expert demonstration of the pool that pre-tests, diagnoses and drills are built from.
struct ExpertDemo {
  Json scenario;             // the task's scenario object
  Json trial;                // the expert's whole trial document (source "expert")
  StepSequence steps;        // what the SkillExtractor reads
  Segmentation skills;       // the extractor's segmentation of `steps`
  Segmentation time_slices;  // the time heuristic's segmentation (the paper's baseline condition)
  double reward = 0.0;       // the expert's episode score (<= 0)
};

class TaskKit {
 public:
  virtual ~TaskKit() = default;

  virtual std::string task() const = 0;  // "parking" or "writing"
  virtual const SkillExtractor& extractor() const = 0;
  // Why the kit uses a fallback extractor (e.g. "assets/models/parking.pt: truncated file; using the time
  // heuristic"), empty when the trained model loaded.
  virtual std::string extractor_notice() const = 0;
  virtual const std::vector<ExpertDemo>& expert_pool() const = 0;
  virtual const DrillProjector& projector() const = 0;
  virtual CurriculumConfig curriculum_config() const = 0;

  // The learner's trial as steps for the extractor, and its episode score: <= 0, 0 best (Alg. 2's r).
  virtual StepSequence steps_of(const Json& trial) const = 0;
  virtual double reward_of(const Json& trial) const = 0;
  // The expert's trial for a scenario (re-planned or looked up), for overlays and the "after" picture.
  virtual Json expert_trial(const Json& scenario) const = 0;

  // Fresh scenarios for evaluation, none equal to any in `exclude` (the pre-test's), deterministic in seed.
  virtual std::vector<Json> fresh_scenarios(int count, std::uint64_t seed, const std::vector<Json>& exclude) const = 0;
  // Plain words for a skill, e.g. "reversing while turning right" or "the loop of 'b'".
  virtual std::string describe_skill(int skill) const = 0;
  // The time a learner gets for a trial of `steps` expert control steps, in seconds.
  virtual double time_limit_seconds(int expert_steps) const = 0;

  // A projected drill (projector().project(plan)) as a trial document the app plays and draws like any
  // trial: parking — {"task":"parking","scenario":{... "start": the drill's initial car state, goal of the
  // last segment's expert}, "actions", "states", "rewards", "success", "source":"drill"}; writing —
  // {"task":"writing","scenario":{"word": the characters the drill's segments come from}, "points": the
  // stitched pen path on the canvas, "source":"drill"}.
  virtual Json drill_trial(const PlayableDrill& drill) const = 0;
  // The score (<= 0, 0 best) of a learner's attempt (a trial document) at a drill. Parking: the attempt's
  // own last-step reward (its scenario carries the drill's start and goal). Writing: the overlap of the
  // attempt's ink with the drill's pen path (the drill is not a whole word, so reward_of would not fit).
  virtual double drill_attempt_reward(const PlayableDrill& drill, const Json& attempt) const = 0;

  // Quality-aware expertise (teaching/expertise/execution_expertise.hpp). The points dynamic time warping
  // aligns an expert's steps with a learner's, one per step (parking: car x, y in m and signed speed in m/s;
  // writing: pen x, y in px).
  virtual std::vector<TracePoint3> trace_points(const StepSequence& steps) const = 0;
  // The task's own reward terms on the learner's steps `path` aligns with the expert's steps [begin, end):
  // <= 0, 0 when the learner's part repeats the expert's.
  virtual double execution_reward(const StepSequence& expert, const StepSequence& learner, const StepAlignment& path,
                                  int begin, int end) const = 0;
  // Other right ways to do the expert's trial on `scenario` (`expert`: its steps), which the execution term
  // may take as the learner's hand (execution_reference.hpp): the same references in the same order for every
  // scenario of this kit. None by default.
  virtual std::vector<ExecutionReference> execution_references(const Json& /*scenario*/,
                                                               const StepSequence& /*expert*/) const {
    return {};
  }
  // What realistic noise alone does to execution_reward on this task with this kit's model (a low percentile
  // of noise-only learners' segment scores, docs/skills.md), for quality-aware expertise's noise-floor rules;
  // nullopt where those rules measured worse (parking) - then the outlier cut alone decides.
  virtual std::optional<NoiseFloor> execution_noise_floor() const = 0;
  // The expertise estimate the trainer diagnoses learners with: the one that measured better on this task's
  // planted weaknesses (docs/skills.md). Research conditions and `diagnose --expertise` may choose either.
  virtual ExpertiseMode learners_expertise() const = 0;
};

}  // namespace sc
