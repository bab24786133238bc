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
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "engine/writing/infill.hpp"
#include "engine/writing/step_data.hpp"
#include "teaching/skills/segmentation_metrics.hpp"
#include "teaching/tasks/parking_drive_reading.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/parking_steps.hpp"
#include "teaching/tasks/task_kit_factory.hpp"
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
  const ChosenExtractor chosen = choose_skill_extractor(args.task, args.model);
  if (!chosen.notice.empty()) std::fprintf(stderr, "skillcoach: note: %s\n", chosen.notice.c_str());
  // A parking trial is read as the kit reads a learner's drive (parking_drive_reading.hpp).
  std::shared_ptr<const SkillExtractor> extractor = chosen.extractor;
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
    throw InputError(args.trial, std::string(e.what()) + " (model " + chosen.model.string() + ")");
  }

  Json out = segmentation_json(segmentation);
  out["task"] = args.task;
  out["file"] = args.trial;
  out["steps"] = steps.length();
  out["extractor"] = extractor->name();
  out["model"] = chosen.model.empty() ? Json(nullptr) : Json(chosen.model.string());
  if (!args.png.empty()) {
    const auto [width, height] = parse_size(args.size, "--size");
    const std::string caption =
        std::filesystem::path(args.trial).filename().string() + "  \xc2\xb7  " +
        (chosen.model.empty() ? "time heuristic" : "CompILE " + chosen.model.filename().string());
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
