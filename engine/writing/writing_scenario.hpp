#pragma once
// A writing scenario (which word, which alphabet, which drawers) and what follows from it: the glyphs, the
// expert's (gold) trajectory and the trial's time limit.
#include <filesystem>
#include <string>

#include "engine/core/json_file.hpp"
#include "engine/writing/alphabet.hpp"
#include "engine/writing/word_trajectory.hpp"

namespace sc::writing {

struct WritingScenario {
  std::string word;  // e.g. "ab-c" (classic) or "B-H^L" (balinese)
  AlphabetKind alphabet = AlphabetKind::Classic;
  DrawerChoice drawers;  // balinese only: {'B': 4} = character02 after drawer 4
  bool operator==(const WritingScenario&) const = default;
};

// {"word": "ab-c", "alphabet": "classic", "drawers": {"B": 4}} ("alphabet" defaults to "classic",
// "drawers" is optional). Validates the word and the drawers; errors name the JSON path.
WritingScenario parse_writing_scenario(const JsonView& node);
Json writing_scenario_json(const WritingScenario& scenario);

GlyphSet load_scenario_glyphs(const WritingScenario& scenario,
                              const std::filesystem::path& data_dir = omniglot_data_dir());
WordTrajectory gold_trajectory(const WritingScenario& scenario,
                               const std::filesystem::path& data_dir = omniglot_data_dir());

// Time rules. The paper gives learners a time limit "proportional to the length of the sequence" without
// numbers; ours: 15 ms per gold step (3x the expert's pace below), at least 3 s. A classic 8-symbol word
// has 1250-2700 steps -> 19-41 s.
inline constexpr double kExpertStepsPerSecond = 200.0;  // the expert's (ghost pen's) writing speed
inline constexpr double kTimeLimitSecondsPerStep = 0.015;
inline constexpr double kMinTimeLimitSeconds = 3.0;
double writing_time_limit_seconds(std::size_t gold_steps);
// Classic words are written in one stroke, so a trial ends when the pen is released; balinese words have
// pen lifts and end with "done" or the time limit.
bool trial_ends_on_release(AlphabetKind kind);

}  // namespace sc::writing
