// skillcoach render: a trial file as a PNG, offscreen (SKILLCOACH_GL=osmesa|egl picks the backend).
// Parking (--size default 1280x720; writing uses the same option): the lot, the path re-simulated from the trial's
// actions, the car at its final state, and with
// --overlay expert the expert's plan for the same scenario as a ghost ribbon.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/task_option.hpp"
#include "app/gui/offscreen_screenshot.hpp"
#include "engine/parking/parking_expert.hpp"
#include "engine/parking_view/parking_trial_image.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/writing/writing_trial.hpp"
#include "engine/writing_view/writing_trial_image.hpp"

namespace sc::cli {
namespace {

struct RenderArgs {
  TaskKind task = TaskKind::parking;
  std::string trajectory;
  std::string out;
  std::string overlay;
  std::string size = "1280x720";
};

int render_parking(const RenderArgs& args, int width, int height) {
  const ParkingTrial trial = read_parking_trial(args.trajectory);
  std::optional<ParkingPath> expert;
  if (args.overlay == "expert") {
    const ParkingPlan plan = ParkingExpert().plan(trial.scenario);
    expert = simulate_parking_path(trial.scenario, plan.actions);
  }
  auto context = create_offscreen_context_from_env(width, height);
  ParkingTrialImageOptions options;
  options.width = width;
  options.height = height;
  options.expert = expert ? &*expert : nullptr;
  write_png(args.out, render_parking_trial_image(*context, trial, options));
  std::printf("%s\n", args.out.c_str());
  return 0;
}

// Writing: the writing view's trial image (engine/writing_view): ink, guide, score, and with --overlay expert
// the gold word as a ghost ribbon.
int render_writing(const RenderArgs& args, int width, int height) {
  const writing::WritingTrial trial = writing::read_writing_trial(args.trajectory);
  for (const auto& warning : trial.warnings)  // e.g. a trace capped at its point limit
    std::fprintf(stderr, "skillcoach: warning: %s\n", warning.c_str());
  writing_view::WritingRenderOptions options;
  options.overlay_expert = args.overlay == "expert";
  options.width = width;
  options.height = height;
  writing_view::render_writing_trial_png(trial, options, args.out);
  std::printf("%s\n", args.out.c_str());
  return 0;
}

CommandRunner setup_render(CLI::App& sub) {
  auto args = std::make_shared<RenderArgs>();
  add_task_option(sub, args->task)->required();
  sub.add_option("--trajectory", args->trajectory, "Trial file (JSON)")->required();
  sub.add_option("--out", args->out, "PNG file to write")->required();
  sub.add_option("--overlay", args->overlay, "Also draw the expert's plan for the same scenario")
      ->check(CLI::IsMember({"expert"}));
  sub.add_option("--size", args->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  return [args] {
    const auto [width, height] = parse_size(args->size, "--size");
    return args->task == TaskKind::writing ? render_writing(*args, width, height)
                                           : render_parking(*args, width, height);
  };
}

const CommandRegistration kRenderCommandRegistration{
    {"render", "Draw a trial file (path, final car, optional expert ghost) into a PNG",
     "skillcoach render --task parking --trajectory trial.json --out trial.png "
     "--overlay expert --size 1280x720",
     setup_render}};

}  // namespace
}  // namespace sc::cli
