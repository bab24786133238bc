#pragma once
// Writing trajectories as step sequences for the SkillExtractor (reference-facts §2.5 layout: 13-D state,
// 2-D actions for the classic alphabet or 3-D with the pen state for the full Balinese alphabet).
#include <string>

#include "engine/writing/step_data.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/skills/skill_extractor.hpp"

namespace sc {

StepSequence writing_step_sequence(const writing::WritingStepData& data);
// A learner's (or the expert's) trial file: the trace is infilled with the reference rule first, so
// learner and expert steps have the same scale.
StepSequence writing_step_sequence(const writing::WritingTrial& trial);
// A pen trace as the skill model sees a learner's: infilled (reference rule), then converted.
StepSequence writing_step_sequence(const writing::TimedTrace& trace, writing::AlphabetKind alphabet,
                                   const std::string& word);

}  // namespace sc
