// skillcoach segment --task T [--model FILE] [--png out.png] TRIAL.json: the trial's skills and boundaries
// as JSON (steps are the trial's control steps for parking, its infilled 1-px pen steps for writing), and
// optionally the trajectory drawn with each segment in its skill's colour and boundaries as dots.
// Without --model the shipped assets/models/<task>.pt is used; when it is missing or unusable the time
// heuristic segments instead and a note on stderr says why (as in the app). A --model that does not load
// (missing, corrupt, truncated, another task, other dimensions) is an error: one line, exit 2.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/segment_image.hpp"
#include "app/cli/task_option.hpp"
#include "app/gui/offscreen_screenshot.hpp"
#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "engine/writing/infill.hpp"
#include "engine/writing/step_data.hpp"
#include "teaching/skills/compile_extractor.hpp"
#include "teaching/skills/segmentation_metrics.hpp"
#include "teaching/skills/time_heuristic_extractor.hpp"
#include "teaching/tasks/parking_drive_reading.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/writing_kit.hpp"
#include "teaching/tasks/writing_steps.hpp"

namespace sc::cli {
namespace {

struct SegmentArgs {
  TaskKind task = TaskKind::parking;
  std::string model;
  std::string png;
  std::string size = "1280x720";
  std::string trial;
};

struct Chosen {
  std::unique_ptr<SkillExtractor> extractor;
  std::string model;  // the file used, empty for the time heuristic
};

Chosen choose_extractor(TaskKind kind, const std::string& model) {
  const bool parking = kind == TaskKind::parking;
  const std::string task(to_string(kind));
  const int state_dim = parking ? kParkingStateDim : writing::kWritingStateDim;
  const int action_dim = parking ? kParkingActionDim : 2;
  if (!model.empty())
    return {std::make_unique<CompileExtractor>(CompileExtractor::load(model, task, state_dim, action_dim)), model};
  const std::filesystem::path shipped = asset_dir() / "models" / (task + ".pt");
  const int slices = parking ? kParkingTimeSlices : kWritingTimeSlices;
  std::string why = "assets/models/" + task + ".pt: missing";
  if (std::filesystem::exists(shipped)) {
    try {
      return {std::make_unique<CompileExtractor>(CompileExtractor::load(shipped, task, state_dim, action_dim)),
              shipped.string()};
    } catch (const InputError& e) {
      why = e.what();
    }
  }
  std::fprintf(stderr, "skillcoach: note: %s; using the time heuristic\n", why.c_str());
  return {std::make_unique<TimeHeuristicExtractor>(slices), ""};
}

Json segmentation_json(const Segmentation& s) {
  Json segments = Json::array();
  for (const SkillSegment& seg : s.segments)
    segments.push_back({{"skill", seg.skill}, {"begin", seg.begin}, {"end", seg.end}});
  return Json{{"skills", s.skills()}, {"boundaries", interior_boundaries(s)}, {"segments", std::move(segments)}};
}

int run(const SegmentArgs& args) {
  const Json doc = read_json_file(args.trial);
  const std::string task(to_string(args.task));
  if (!doc.is_object() || !doc.contains("task") || doc["task"] != task)
    throw InputError(args.trial, "not a " + task + " trial ($.task is not \"" + task + "\")");
  Chosen chosen = choose_extractor(args.task, args.model);
  // A parking trial is read as the kit reads a learner's drive (parking_drive_reading.hpp).
  std::shared_ptr<const SkillExtractor> extractor = std::move(chosen.extractor);
  if (args.task == TaskKind::parking)
    extractor = parking_drive_reader(std::move(extractor), shipped_pool_piece_length());

  StepSequence steps;
  std::optional<ParkingTrial> parking;
  std::optional<writing::WritingTrial> writing_trial;
  std::vector<writing::TracePoint> points;
  if (args.task == TaskKind::parking) {
    parking = parse_parking_trial(doc, args.trial);
    steps = parking_step_sequence(*parking);
  } else {
    writing_trial = writing::parse_writing_trial(doc, args.trial);
    for (const auto& warning : writing_trial->warnings)  // e.g. a trace capped at its point limit
      std::fprintf(stderr, "skillcoach: warning: %s\n", warning.c_str());
    points = writing::infill_trace(writing_trial->trace()).points;
    steps = writing_step_sequence(
        writing::trace_step_data(points, writing_trial->scenario.alphabet, writing_trial->scenario.word));
  }
  if (steps.length() == 0) throw InputError(args.trial, "trial has no steps to segment");
  Segmentation segmentation;
  try {
    segmentation = extractor->extract(steps);
  } catch (const InputError& e) {
    throw InputError(args.trial, std::string(e.what()) + " (model " + chosen.model + ")");
  }

  Json out = segmentation_json(segmentation);
  out["task"] = args.task;
  out["file"] = args.trial;
  out["steps"] = steps.length();
  out["extractor"] = extractor->name();
  out["model"] = chosen.model.empty() ? Json(nullptr) : Json(chosen.model);
  if (!args.png.empty()) {
    const auto [width, height] = parse_size(args.size, "--size");
    const std::string caption =
        std::filesystem::path(args.trial).filename().string() + "  \xc2\xb7  " +
        (chosen.model.empty() ? "time heuristic"
                              : "CompILE " + std::filesystem::path(chosen.model).filename().string());
    write_png(args.png, parking
                            ? render_parking_segments(*parking, segmentation, caption, width, height)
                            : render_writing_segments(*writing_trial, points, segmentation, caption, width, height));
    out["png"] = args.png;
  }
  std::printf("%s\n", out.dump(1).c_str());
  return 0;
}

CommandRunner setup_segment(CLI::App& sub) {
  auto args = std::make_shared<SegmentArgs>();
  add_task_option(sub, args->task)->required();
  sub.add_option("--model", args->model,
                 "CompILE model file (default: assets/models/<task>.pt, else the time heuristic)");
  sub.add_option("--png", args->png, "Also draw the segments into this PNG");
  sub.add_option("--size", args->size, "PNG size WIDTHxHEIGHT")->capture_default_str();
  sub.add_option("trial", args->trial, "Trial file (JSON)")->required();
  return [args] { return run(*args); };
}

const CommandRegistration kSegmentCommandRegistration{
    {"segment", "Split a trial into skills (JSON), optionally drawn by skill into a PNG",
     "skillcoach segment --task writing --png word.png trial.json", setup_segment}};

}  // namespace
}  // namespace sc::cli
