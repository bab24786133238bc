// skillcoach simulate-students [--seed S] [--out-dir DIR] [--quick] ...: the paper's synthetic-student
// experiment (teaching/students/student_experiment.hpp) on the parking kit. Prints the table, writes
// DIR/students.json (every number), DIR/students.png (bar chart of mean reward and success rate, ± s.e. over
// the sets) and DIR/students_curve.png (the appendix learning curve).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "app/cli/command_registry.hpp"
#include "app/cli/experiment_progress.hpp"
#include "app/cli/simulate_writing_students.hpp"
#include "app/cli/task_option.hpp"
#include "engine/core/json_file.hpp"
#include "engine/render/bar_chart_image.hpp"
#include "engine/render/line_chart_image.hpp"
#include "teaching/students/expert_drives.hpp"
#include "teaching/students/student_report.hpp"
#include "teaching/tasks/parking_kit.hpp"
#include "teaching/tasks/task_kit_factory.hpp"

namespace sc::cli {
namespace {

struct SimulateArgs {
  unsigned long long seed = 0;
  std::string out_dir = "simulate-students";
  std::string model;
  int pairs = 0;
  double rehearsal = 0.0;
  int finetune_epochs = 0;     // 0: the config's
  double finetune_lr = 0.0;    // 0: the config's
  int student_drives = 0;      // 0: the config's
  double reverse_keep = -1.0;  // < 0: the recipe's (0.2, the paper)
  bool study_corner = false;
  bool no_curve = false;
  bool quick = false;
  TaskKind task = TaskKind::parking;
  WritingSimulateArgs writing;  // --task writing: the shared options are copied in, plus the writing-only ones
};

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
  auto group = [&](const StudentResult& s) {
    BarGroup r{std::string(student_name(s.recipe.kind)), {}, {}}, p = r;
    auto add = [&](const std::vector<double>& rewards, const std::vector<double>& successes) {
      if (rewards.empty()) {  // the fully trained yardstick is not fine-tuned: no bar
        for (BarGroup* g : {&r, &p}) {
          g->values.push_back(std::nan(""));
          g->errors.push_back(0.0);
        }
        return;
      }
      const MeanAndError mr = mean_and_standard_error(rewards), ms = mean_and_standard_error(successes);
      r.values.push_back(mr.mean);
      r.errors.push_back(mr.standard_error);
      p.values.push_back(100.0 * ms.mean);
      p.errors.push_back(100.0 * ms.standard_error);
    };
    add(s.before_reward, s.before_success);
    for (StudyCondition c : {StudyCondition::FullTrajectory, StudyCondition::Drills, StudyCondition::IndDrills}) {
      const bool tuned = !s.conditions.empty();
      add(tuned ? s.of(c).reward : std::vector<double>{}, tuned ? s.of(c).success : std::vector<double>{});
    }
    reward.groups.push_back(std::move(r));
    success.groups.push_back(std::move(p));
  };
  group(result.reference);
  for (const StudentResult& s : result.students) group(s);
  figure.panels = {std::move(reward), std::move(success)};
  figure.notes.push_back("skills: " + result.extractor +
                         (result.extractor_notice.empty() ? "" : " (" + result.extractor_notice + ")") + "; seed " +
                         std::to_string(result.config.seed) + "; " + std::to_string(result.config.scenarios_per_set) +
                         " fresh scenarios per set; fine-tuned " + std::to_string(result.config.finetune_epochs) +
                         " epochs on equal-size data");
  return figure;
}

std::string format_g(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

LineChartFigure curve_chart_of(const StudentExperimentResult& result) {
  const LearningCurve& curve = *result.curve;
  LineChartFigure figure;
  figure.title = "Reversing-difficulty student fine-tuned on a fixed set of 3 Ind. Drills";
  figure.x_label = "fine-tuning epochs";
  LineSeries reward{"reversing-difficulty student", Color::hex(0xe0833a), {}, {}}, success = reward;
  for (const LearningCurvePoint& p : curve.points) {
    reward.x.push_back(p.epochs);
    reward.y.push_back(p.score.mean_reward);
    success.x.push_back(p.epochs);
    success.y.push_back(100.0 * p.score.success_rate);
  }
  const Color expert = Color::hex(0x3a8f5c);
  figure.panels = {
      {"episode reward (last step), mean of " + std::to_string(result.config.curve.rollouts) + " rollouts",
       "%.3f",
       {reward},
       {{"expert planner", expert, curve.expert.mean_reward}}},
      {"success rate (%)", "%.0f", {success}, {{"expert planner", expert, 100.0 * curve.expert.success_rate}}}};
  figure.notes.push_back(
      "seed " + std::to_string(result.config.seed) + "; drills: " + std::to_string(curve.drill_pairs) + " pairs (" +
      std::to_string(curve.reverse_pairs) + " reversing)" +
      (curve.rehearsal_pairs > 0 ? " + " + std::to_string(curve.rehearsal_pairs) + " of its own pairs" : "") + "; lr " +
      format_g(result.config.finetune_learning_rate) + "; goals: " + std::string(to_string(result.config.region)));
  return figure;
}

// The kit whose pool supplies diagnosis scenarios and drills: the shipped pool of the whole lot or of the
// study corner.
std::unique_ptr<TaskKit> experiment_kit(const SimulateArgs& args) {
  return make_task_kit(TaskKind::parking, args.model,
                       args.study_corner ? GoalRegion::StudyCorner : GoalRegion::WholeLot);
}

StudentExperimentConfig config_of(const SimulateArgs& args) {
  StudentExperimentConfig config = args.quick ? StudentExperimentConfig::quick() : StudentExperimentConfig::paper();
  config.seed = args.seed;
  config.finetune_pairs = args.pairs;
  config.finetune_rehearsal = args.rehearsal;
  if (args.finetune_epochs > 0) config.finetune_epochs = args.finetune_epochs;
  if (args.finetune_lr > 0) config.finetune_learning_rate = args.finetune_lr;
  if (args.student_drives > 0) config.student_drives = args.student_drives;
  if (args.study_corner) config.region = GoalRegion::StudyCorner;
  for (SyntheticStudentRecipe& r : config.students)
    if (r.kind == SyntheticStudentKind::ReversingDifficulty && args.reverse_keep >= 0)
      r.reverse_keep_fraction = args.reverse_keep;
  config.learning_curve = !args.no_curve;
  return config;
}

int run_writing(const SimulateArgs& args) {
  WritingSimulateArgs w = args.writing;
  w.seed = args.seed;
  w.out_dir = args.out_dir;
  w.model = args.model;
  w.pairs = args.pairs;
  w.rehearsal = args.rehearsal;
  w.quick = args.quick;
  w.finetune_epochs = args.finetune_epochs;
  w.finetune_learning_rate = args.finetune_lr;
  return run_writing_students(w);
}

int run(const SimulateArgs& args) {
  if (args.task == TaskKind::writing) return run_writing(args);
  const StudentExperimentConfig config = config_of(args);
  config.validate();
  const std::unique_ptr<TaskKit> kit = experiment_kit(args);
  if (!kit->extractor_notice().empty()) std::fprintf(stderr, "skillcoach: note: %s\n", kit->extractor_notice().c_str());
  const StudentExperimentResult result = run_student_experiment(*kit, config, progress_printer());
  std::printf("%s", student_experiment_table(result, *kit).c_str());

  const std::filesystem::path dir(args.out_dir);
  std::filesystem::create_directories(dir);
  write_json_file(dir / "students.json", student_experiment_json(result, *kit));
  const BarChartFigure figure = chart_of(result);
  auto context = create_offscreen_context_from_env(figure.width, figure.height);
  write_png(dir / "students.png", render_bar_chart_figure(*context, figure));
  std::printf("\nwrote %s, %s", (dir / "students.json").string().c_str(), (dir / "students.png").string().c_str());
  if (result.curve) {
    write_png(dir / "students_curve.png", render_line_chart_figure(*context, curve_chart_of(result)));
    std::printf(", %s", (dir / "students_curve.png").string().c_str());
  }
  std::printf("\n");
  return 0;
}

CommandRunner setup_simulate_students(CLI::App& sub) {
  auto args = std::make_shared<SimulateArgs>();
  sub.add_option("--seed", args->seed, "Seed of students, scenarios and fine-tuning data (default 0)")
      ->check(CLI::Validator(
          [](std::string& v) { return v.starts_with('-') ? std::string("must not be negative") : ""; }, "SEED >= 0"));
  sub.add_option("--out-dir", args->out_dir, "Where students.json and students.png go (default simulate-students)");
  sub.add_option("--model", args->model,
                 "CompILE model file (default: assets/models/parking.pt, else the time heuristic)");
  sub.add_option("--pairs", args->pairs,
                 "Fine-tuning pairs per condition (default 0: one round of Ind. Drills per set)")
      ->check(CLI::NonNegativeNumber);
  sub.add_option(
         "--rehearsal", args->rehearsal,
         "Ours: add this many times the condition's pairs of the student's own training pairs (default 0: the paper)")
      ->check(CLI::Range(0.0, 100.0));
  add_task_option(sub, args->task, "parking (default) or writing");
  sub.add_option("--finetune-epochs", args->finetune_epochs,
                 "Fine-tuning epochs (default: parking 100, the paper; writing 10)")
      ->check(CLI::Range(1, 100000));
  sub.add_option("--finetune-lr", args->finetune_lr, "Fine-tuning learning rate (default 5e-4, the students' own)")
      ->check(CLI::Range(1e-7, 1.0));
  sub.add_option("--student-drives", args->student_drives,
                 "Expert drives the students are cloned on, apart from the teaching pool (default 600)")
      ->check(CLI::Range(1, 100000));
  sub.add_option(
         "--reverse-keep", args->reverse_keep,
         "Share of the reverse-acceleration pairs the reversing-difficulty student keeps (default 0.2, the paper)")
      ->check(CLI::Range(0.0, 1.0));
  sub.add_flag("--study-corner", args->study_corner,
               "The paper's study subset: pool and evaluation goals in the bottom-right corner (spots 12-14)");
  sub.add_flag("--no-curve", args->no_curve, "Skip the appendix learning curve (students_curve.png)");
  add_writing_student_options(sub, args->writing);
  sub.add_flag("--quick", args->quick, "Tiny students, few sets: checks the pipeline in seconds, concludes nothing");
  return [args] { return run(*args); };
}

const CommandRegistration kSimulateStudentsCommandRegistration{
    {"simulate-students",
     "Synthetic students (parking or writing) fine-tuned on Ind. Drills vs Drills vs Full Trajectory",
     "skillcoach simulate-students --seed 0 --out-dir docs", setup_simulate_students}};

}  // namespace
}  // namespace sc::cli
