#pragma once
// Writing trial files (docs/trajectory-format.md, "Writing trials"):
//   {"task": "writing",
//    "scenario": {"word": "ab-c", "alphabet": "classic"},
//    "points": [[x, y], [x, y, pen], ...],        canvas pixels, y down; pen 1 = ink into this point
//    "t": [seconds, ...],                          optional, one per point, non-decreasing
//    "score": -0.42, "source": "learner", "device": "mouse"}   optional
// Unknown fields are ignored. Malformed files throw one InputError line naming the file, JSON path and
// problem; NaN/Inf and coordinates far outside the canvas are rejected; traces longer than kMaxTrialPoints
// are cut with a warning.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/writing/infill.hpp"
#include "engine/writing/writing_scenario.hpp"

namespace sc::writing {

inline constexpr std::size_t kMaxTrialPoints = 200000;  // ~14 min of 240 Hz samples
inline constexpr double kMaxCoordinate = 10000.0;       // px; the canvas is 500 x 300

struct WritingTrial {
  WritingScenario scenario;
  std::vector<TracePoint> points;
  std::vector<double> times;  // "t": empty, or one time stamp (seconds) per point
  std::optional<double> score;
  std::string source;                 // "learner", "expert", ...
  std::string device;                 // "mouse", "trackpad", ...
  std::vector<std::string> warnings;  // problems repaired while reading (not written back)

  TimedTrace trace() const { return {points, times}; }
};

WritingTrial parse_writing_trial(const Json& doc, std::string_view source);
WritingTrial read_writing_trial(const std::filesystem::path& file);
// Points are written as [x, y] when every pen flag is 1, else as [x, y, pen].
Json writing_trial_json(const WritingTrial& trial);
void write_writing_trial(const std::filesystem::path& file, const WritingTrial& trial);

// The expert's trial for a scenario: the gold trajectory's points, time-stamped at kExpertStepsPerSecond,
// source "expert".
WritingTrial gold_trial(const WritingScenario& scenario, const std::filesystem::path& data_dir = omniglot_data_dir());
WritingTrial gold_trial(const WritingScenario& scenario, const WordTrajectory& gold);

}  // namespace sc::writing
