// skillcoach score --task writing FILE.json: scores a trial against the gold (expert) trajectory and prints
// the score and its parts as JSON (see docs/writing-score.md).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "engine/writing/writing_score.hpp"
#include "engine/writing/writing_trial.hpp"

namespace sc::cli {
namespace {

struct ScoreArgs {
  std::string task;
  std::string file;
};

int score_writing_file(const std::string& file) {
  const auto trial = writing::read_writing_trial(file);
  for (const auto& warning : trial.warnings) std::fprintf(stderr, "skillcoach: warning: %s\n", warning.c_str());
  const auto gold = writing::gold_trajectory(trial.scenario);
  const writing::WritingScoreParams params;
  const auto score = writing::score_writing(gold.points(), trial.points, params);
  Json out = writing::writing_score_json(score, params);
  out["file"] = file;
  out["scenario"] = writing::writing_scenario_json(trial.scenario);
  out["learner_points"] = trial.points.size();
  if (trial.score) out["stored_score"] = *trial.score;
  std::printf("%s\n", out.dump(1).c_str());
  return 0;
}

CommandRunner setup_score(CLI::App& sub) {
  auto args = std::make_shared<ScoreArgs>();
  sub.add_option("--task", args->task, "Task of the trial")->required()->check(CLI::IsMember({"writing"}));
  sub.add_option("file", args->file, "Trial file (JSON)")->required();
  return [args] { return score_writing_file(args->file); };
}

const CommandRegistration kScoreCommandRegistration{
    {"score", "Score a trial file against the expert and print the score and its parts (JSON)",
     "skillcoach score --task writing trial.json", setup_score}};

}  // namespace
}  // namespace sc::cli
