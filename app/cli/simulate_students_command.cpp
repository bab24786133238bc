// skillcoach simulate-students [--seed S] [--out-dir DIR] [--quick]: the paper's synthetic-student experiment
// (teaching/students/student_experiment.hpp) on the parking kit. Prints the table, writes DIR/students.json
// (every number) and DIR/students.png (bar chart of mean reward and success rate, ± s.e. over the sets).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/simulate_writing_students.hpp"
#include "engine/core/json_file.hpp"
#include "engine/render/bar_chart_image.hpp"
#include "teaching/students/student_report.hpp"
#include "teaching/tasks/task_kit_factory.hpp"

namespace sc::cli {
namespace {

struct SimulateArgs {
  unsigned long long seed = 0;
  std::string out_dir = "simulate-students";
  std::string model;
  int pairs = 0;
  double rehearsal = 0.0;
  bool quick = false;
  std::string task = "parking";
  WritingSimulateArgs writing;  // --task writing: the shared options are copied in, plus the writing-only ones
};

// One updating line on a terminal; otherwise one line per finished phase (logs stay short).
ExperimentProgress progress_printer() {
  const bool tty = isatty(STDERR_FILENO) != 0;
  const auto start = std::chrono::steady_clock::now();
  return [tty, start](std::string_view phase, int done, int total) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (tty)
      std::fprintf(stderr, "\r\033[K[%6.1f s] %.*s %d/%d%s", seconds, static_cast<int>(phase.size()), phase.data(), done,
                   total, done == total ? "\n" : "");
    else if (done == total)
      std::fprintf(stderr, "[%6.1f s] %.*s done\n", seconds, static_cast<int>(phase.size()), phase.data());
  };
}

BarChartFigure chart_of(const StudentExperimentResult& result) {
  BarChartFigure figure;
  figure.title = "Synthetic parking students after fine-tuning (mean ± s.e. over " +
                 std::to_string(result.config.evaluation_sets) + " evaluation sets)";
  figure.series = {{"before fine-tuning", Color::hex(0xb8bec7)},
                   {std::string(condition_name(StudyCondition::FullTrajectory)), Color::hex(0x8a6fd1)},
                   {std::string(condition_name(StudyCondition::Drills)), Color::hex(0x4a9fd8)},
                   {std::string(condition_name(StudyCondition::IndDrills)), Color::hex(0xe0833a)}};
  BarChartPanel reward{"episode reward (last step, higher is better)", "%.3f", {}};
  BarChartPanel success{"success rate (%)", "%.0f", {}};
  for (const StudentResult& s : result.students) {
    BarGroup r{std::string(student_name(s.recipe.kind)), {}, {}}, p = r;
    auto add = [&](const std::vector<double>& rewards, const std::vector<double>& successes) {
      const MeanAndError mr = mean_and_standard_error(rewards), ms = mean_and_standard_error(successes);
      r.values.push_back(mr.mean);
      r.errors.push_back(mr.standard_error);
      p.values.push_back(100.0 * ms.mean);
      p.errors.push_back(100.0 * ms.standard_error);
    };
    add(s.before_reward, s.before_success);
    for (StudyCondition c : {StudyCondition::FullTrajectory, StudyCondition::Drills, StudyCondition::IndDrills})
      add(s.of(c).reward, s.of(c).success);
    reward.groups.push_back(std::move(r));
    success.groups.push_back(std::move(p));
  }
  figure.panels = {std::move(reward), std::move(success)};
  figure.notes.push_back("skills: " + result.extractor + (result.extractor_notice.empty() ? "" : " (" + result.extractor_notice + ")") +
                         "; seed " + std::to_string(result.config.seed) + "; " + std::to_string(result.config.scenarios_per_set) +
                         " fresh scenarios per set; fine-tuned " + std::to_string(result.config.finetune_epochs) +
                         " epochs on equal-size data");
  return figure;
}

int run(const SimulateArgs& args) {
  if (args.task == "writing") {
    WritingSimulateArgs w = args.writing;
    w.seed = args.seed;
    w.out_dir = args.out_dir;
    w.model = args.model;
    w.pairs = args.pairs;
    w.rehearsal = args.rehearsal;
    w.quick = args.quick;
    return run_writing_students(w);
  }
  StudentExperimentConfig config = args.quick ? StudentExperimentConfig::quick() : StudentExperimentConfig::paper();
  config.seed = args.seed;
  config.finetune_pairs = args.pairs;
  config.finetune_rehearsal = args.rehearsal;
  const std::unique_ptr<TaskKit> kit = make_task_kit("parking", args.model);
  if (!kit->extractor_notice().empty()) std::fprintf(stderr, "skillcoach: note: %s\n", kit->extractor_notice().c_str());
  const StudentExperimentResult result = run_student_experiment(*kit, config, progress_printer());
  std::printf("%s", student_experiment_table(result, *kit).c_str());

  const std::filesystem::path dir(args.out_dir);
  std::filesystem::create_directories(dir);
  write_json_file(dir / "students.json", student_experiment_json(result, *kit));
  const BarChartFigure figure = chart_of(result);
  auto context = create_offscreen_context_from_env(figure.width, figure.height);
  write_png(dir / "students.png", render_bar_chart_figure(*context, figure));
  std::printf("\nwrote %s and %s\n", (dir / "students.json").string().c_str(), (dir / "students.png").string().c_str());
  return 0;
}

CommandRunner setup(CLI::App& sub) {
  auto args = std::make_shared<SimulateArgs>();
  sub.add_option("--seed", args->seed, "Seed of students, scenarios and fine-tuning data (default 0)");
  sub.add_option("--out-dir", args->out_dir, "Where students.json and students.png go (default simulate-students)");
  sub.add_option("--model", args->model, "CompILE model file (default: assets/models/parking.pt, else the time heuristic)");
  sub.add_option("--pairs", args->pairs, "Fine-tuning pairs per condition (default 0: one round of Ind. Drills per set)")
      ->check(CLI::NonNegativeNumber);
  sub.add_option("--rehearsal", args->rehearsal,
                 "Ours: add this many times the condition's pairs of the student's own training pairs (default 0: the paper)")
      ->check(CLI::Range(0.0, 100.0));
  sub.add_option("--task", args->task, "parking (default) or writing")->check(CLI::IsMember({"parking", "writing"}));
  add_writing_student_options(sub, args->writing);
  sub.add_flag("--quick", args->quick, "Tiny students, few sets: checks the pipeline in seconds, concludes nothing");
  return [args] { return run(*args); };
}

const CommandRegistration kReg{{"simulate-students",
                                "Synthetic parking students fine-tuned on Ind. Drills vs Drills vs Full Trajectory",
                                "skillcoach simulate-students --seed 0 --out-dir docs", setup}};

}  // namespace
}  // namespace sc::cli
