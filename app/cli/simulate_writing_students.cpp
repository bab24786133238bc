#include "app/cli/simulate_writing_students.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/cli/experiment_progress.hpp"
#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "engine/render/bar_chart_image.hpp"
#include "teaching/students/writing_student_report.hpp"
#include "teaching/tasks/task_kit_factory.hpp"

namespace sc::cli {
namespace {

BarChartFigure chart_of(const WritingStudentExperimentResult& result) {
  BarChartFigure figure;
  figure.title = "Synthetic writing students after fine-tuning (mean ± s.e. over ";
  figure.title.append(std::to_string(result.config.evaluation_sets)).append(" evaluation sets)");
  figure.series = {{"before fine-tuning", Color::hex(0xb8bec7)},
                   {std::string(condition_name(StudyCondition::FullTrajectory)), Color::hex(0x8a6fd1)},
                   {std::string(condition_name(StudyCondition::Drills)), Color::hex(0x4a9fd8)},
                   {std::string(condition_name(StudyCondition::IndDrills)), Color::hex(0xe0833a)}};
  BarChartPanel reward{"overlap reward on fresh words (higher is better, 0 = perfect)", "%.2f", {}};
  for (const WritingStudentResult& s : result.students) {
    BarGroup g{s.recipe.name(), {}, {}};
    auto add = [&](const std::vector<double>& rewards) {
      const MeanAndError m = mean_and_standard_error(rewards);
      g.values.push_back(m.mean);
      g.errors.push_back(m.standard_error);
    };
    add(s.before_reward);
    for (StudyCondition c : {StudyCondition::FullTrajectory, StudyCondition::Drills, StudyCondition::IndDrills})
      add(s.of(c).reward);
    reward.groups.push_back(std::move(g));
  }
  figure.panels = {std::move(reward)};
  const WritingStudentExperimentConfig& c = result.config;
  char tuning[160];
  std::snprintf(tuning, sizeof tuning, "fine-tuned %d epochs at lr %g on equal-size data, rehearsal %g x pairs",
                c.finetune_epochs, c.finetune_learning_rate, c.finetune_rehearsal);
  std::string note = "skills: ";
  note.append(result.extractor).append("; seed ").append(std::to_string(c.seed)).append("; ");
  note.append(std::to_string(c.words_per_set)).append(" fresh words per set; ").append(tuning);
  figure.notes.push_back(note);
  return figure;
}

WritingStudentExperimentConfig config_of(const WritingSimulateArgs& args) {
  WritingStudentExperimentConfig config =
      args.quick ? WritingStudentExperimentConfig::quick() : WritingStudentExperimentConfig::standard();
  config.seed = args.seed;
  config.finetune_pairs = args.pairs;
  config.finetune_rehearsal = args.rehearsal;
  if (args.finetune_epochs > 0) config.finetune_epochs = args.finetune_epochs;
  if (args.finetune_learning_rate > 0.0) config.finetune_learning_rate = args.finetune_learning_rate;
  if (args.words_per_set > 0) config.words_per_set = args.words_per_set;
  if (args.targets > 0) config.num_targets = args.targets;
  return config;
}

}  // namespace

void add_writing_student_options(CLI::App& sub, WritingSimulateArgs& args) {
  sub.add_option("--words-per-set", args.words_per_set, "Writing: fresh words per evaluation set (default 2)")
      ->check(CLI::Range(1, 30));
  sub.add_option("--targets", args.targets, "Writing: weakest skills that get Ind. Drills (default 3)")
      ->check(CLI::Range(1, 24));
}

int run_writing_students(const WritingSimulateArgs& args) {
  const WritingStudentExperimentConfig config = config_of(args);
  const std::unique_ptr<TaskKit> kit = make_task_kit("writing", args.model);
  const auto* writing_kit = dynamic_cast<const WritingKit*>(kit.get());
  if (writing_kit == nullptr) throw InputError("simulate-students", "the writing task did not give a writing kit");
  if (!kit->extractor_notice().empty()) std::fprintf(stderr, "skillcoach: note: %s\n", kit->extractor_notice().c_str());
  const WritingStudentExperimentResult result =
      run_writing_student_experiment(*writing_kit, config, progress_printer());
  std::printf("%s", writing_experiment_table(result, *writing_kit).c_str());

  const std::filesystem::path dir(args.out_dir);
  std::filesystem::create_directories(dir);
  write_json_file(dir / "writing_students.json", writing_experiment_json(result, *writing_kit));
  const BarChartFigure figure = chart_of(result);
  auto context = create_offscreen_context_from_env(figure.width, figure.height);
  write_png(dir / "writing_students.png", render_bar_chart_figure(*context, figure));
  std::printf("\nwrote %s and %s\n", (dir / "writing_students.json").string().c_str(),
              (dir / "writing_students.png").string().c_str());
  return 0;
}

}  // namespace sc::cli
