#include "teaching/students/writing_student_report.hpp"

#include <cstdio>
#include <string_view>

namespace sc {
namespace {

std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0) {
  char text[128];
  std::snprintf(text, sizeof text, fmt, a, b, c);
  return text;
}

// Appends `text` left-aligned in a column of `width` characters plus one space (in place: GCC 12's
// -Wrestrict misfires on chained string concatenation).
void cell(std::string& out, std::string_view text, std::size_t width) {
  out.append(text);
  if (text.size() < width) out.append(width - text.size(), ' ');
  out.push_back(' ');
}

double mean_of(const std::vector<int>& values) {
  double total = 0.0;
  for (int v : values) total += v;
  return values.empty() ? 0.0 : total / static_cast<double>(values.size());
}

std::string reward_cell(const std::vector<double>& values) {
  const MeanAndError m = mean_and_standard_error(values);
  return format("%7.4f ± %.4f", m.mean, m.standard_error);
}

Json stats_json(const std::vector<double>& values) {
  const MeanAndError m = mean_and_standard_error(values);
  return {{"mean", m.mean}, {"standard_error", m.standard_error}, {"per_set", values}};
}

const std::vector<double>& rewards_of(const WritingStudentResult& s, const std::string& name) {
  if (name == "before") return s.before_reward;
  for (const WritingConditionResult& c : s.conditions)
    if (condition_name(c.condition) == name) return c.reward;
  return s.before_reward;
}

void config_lines(std::string& out, const WritingStudentExperimentResult& result) {
  const WritingStudentExperimentConfig& c = result.config;
  out.append("Synthetic writing students: ").append(std::to_string(c.evaluation_sets)).append(" evaluation sets of ");
  out.append(std::to_string(c.words_per_set)).append(" fresh words, overlap reward mean ± s.e. over sets (seed ");
  out.append(std::to_string(c.seed)).append(")\nskills: ").append(result.extractor);
  if (!result.extractor_notice.empty()) out.append(" (").append(result.extractor_notice).append(")");
  out.append("; expert pool ").append(std::to_string(result.pool_size)).append(" words, ");
  out.append(std::to_string(result.expert_pairs)).append(" pairs\n");
  const WritingStudentRecipe& r = c.students.front();
  out.append(format("students: MLP hidden %.0f, %.0f epochs", r.hidden, r.epochs));
  out.append(format(", lr %g, batch %.0f; ", r.learning_rate, r.batch_size));
  out.append(format("fine-tuning: %.0f epochs, lr %g, rehearsal %g x pairs, equal-size data per set\n",
                    c.finetune_epochs, c.finetune_learning_rate, c.finetune_rehearsal));
}

void student_rows(std::string& out, const WritingStudentResult& s) {
  cell(out, s.recipe.name(), 16);
  cell(out, "before", 16);
  out.append(reward_cell(s.before_reward)).append("\n");
  for (const WritingConditionResult& c : s.conditions) {
    cell(out, "", 16);
    cell(out, condition_name(c.condition), 16);
    cell(out, reward_cell(c.reward), 20);
    out.append(format("%8.1f %8.1f\n", mean_of(c.pairs), mean_of(c.letter_pairs)));
  }
}

void diagnosis_line(std::string& out, const WritingStudentResult& s, const WritingKit& kit) {
  out.append("  ");
  cell(out, s.recipe.name(), 16);
  out.append(format("reward %.4f, MSE %.4f (train %.4f):", s.diagnosis_reward, s.expert_mse, s.training_loss));
  for (int m : s.diagnosis.targets) {
    out.append(" ").append(std::to_string(m)).append(" (").append(kit.describe_skill(m));
    out.append(format(", E %.3f)", s.diagnosis.expertise[static_cast<std::size_t>(m)]));
  }
  out.append("\n");
}

}  // namespace

std::vector<WritingComparison> compare_writing_conditions(const WritingStudentExperimentResult& result) {
  const std::pair<std::string, std::string> pairs[] = {{"Ind. Drills", "Full Trajectory"},
                                                       {"Drills", "Full Trajectory"},
                                                       {"Ind. Drills", "Drills"},
                                                       {"Ind. Drills", "before"}};
  std::vector<WritingComparison> out;
  for (std::size_t s = 0; s < result.students.size(); ++s)
    for (const auto& [a, b] : pairs) {
      const std::vector<double>& ra = rewards_of(result.students[s], a);
      const std::vector<double>& rb = rewards_of(result.students[s], b);
      WritingComparison c{static_cast<int>(s), a, b, 0.0, wilcoxon_signed_rank(ra, rb)};
      for (std::size_t k = 0; k < ra.size(); ++k) c.mean_difference += (ra[k] - rb[k]) / static_cast<double>(ra.size());
      out.push_back(c);
    }
  return out;
}

std::string writing_experiment_table(const WritingStudentExperimentResult& result, const WritingKit& kit) {
  std::string out;
  config_lines(out, result);
  out += "\nstudent          condition        overlap reward          pairs  letter\n";
  for (const WritingStudentResult& s : result.students) student_rows(out, s);
  out.append("\nweakest skills (Alg. 2 on the student's traces of ")
      .append(std::to_string(result.diagnosis_words.size()));
  out.append(" diverse pool words):\n");
  for (const WritingStudentResult& s : result.students) diagnosis_line(out, s, kit);
  out += "\nWilcoxon signed-rank tests on the per-set mean reward (two-sided, paired by set):\n";
  for (const WritingComparison& c : compare_writing_conditions(result)) {
    out += "  ";
    cell(out, result.students[static_cast<std::size_t>(c.student)].recipe.name(), 16);
    std::string pair = c.a;
    pair.append(" vs ").append(c.b);
    cell(out, pair, 32);
    out.append(format("diff %+.4f  W+ %5.1f", c.mean_difference, c.test.w_plus));
    out.append(format("  W- %5.1f  p = %.4f", c.test.w_minus, c.test.p_two_sided));
    out.append(c.test.p_two_sided < 0.05 ? " *\n" : "\n");
  }
  return out;
}

Json writing_experiment_json(const WritingStudentExperimentResult& result, const WritingKit& kit) {
  const WritingStudentExperimentConfig& c = result.config;
  Json students = Json::array();
  for (const WritingStudentResult& s : result.students) {
    Json conditions = Json::object();
    for (const WritingConditionResult& cr : s.conditions)
      conditions[std::string(condition_name(cr.condition))] = {{"reward", stats_json(cr.reward)},
                                                               {"pairs", cr.pairs},
                                                               {"letter_pairs", cr.letter_pairs},
                                                               {"finetune_loss", cr.finetune_loss},
                                                               {"rehearsal_pairs", cr.rehearsal_pairs}};
    Json targets = Json::array();
    for (int m : s.diagnosis.targets)
      targets.push_back({{"skill", m},
                         {"description", kit.describe_skill(m)},
                         {"expertise", s.diagnosis.expertise[static_cast<std::size_t>(m)]}});
    students.push_back({{"student", s.recipe.key()},
                        {"name", s.recipe.name()},
                        {"epochs", s.recipe.epochs},
                        {"hidden", s.recipe.hidden},
                        {"learning_rate", s.recipe.learning_rate},
                        {"training_pairs", s.training_pairs},
                        {"letter_pairs", s.letter_pairs},
                        {"training_loss", s.training_loss},
                        {"expert_mse", s.expert_mse},
                        {"diagnosis_reward", s.diagnosis_reward},
                        {"weakest_skills", targets},
                        {"before", stats_json(s.before_reward)},
                        {"conditions", conditions}});
  }
  Json tests = Json::array();
  for (const WritingComparison& t : compare_writing_conditions(result))
    tests.push_back({{"student", result.students[static_cast<std::size_t>(t.student)].recipe.key()},
                     {"a", t.a},
                     {"b", t.b},
                     {"mean_difference", t.mean_difference},
                     {"n", t.test.n},
                     {"w_plus", t.test.w_plus},
                     {"w_minus", t.test.w_minus},
                     {"p_two_sided", t.test.p_two_sided},
                     {"exact", t.test.exact}});
  return {{"task", "writing"},
          {"seed", c.seed},
          {"extractor", result.extractor},
          {"extractor_notice", result.extractor_notice},
          {"pool_words", result.pool_size},
          {"expert_pairs", result.expert_pairs},
          {"diagnosis_words", result.diagnosis_words},
          {"evaluation_words", result.evaluation_words},
          {"num_targets", c.num_targets},
          {"finetune_epochs", c.finetune_epochs},
          {"finetune_learning_rate", c.finetune_learning_rate},
          {"finetune_pairs", c.finetune_pairs},
          {"finetune_rehearsal", c.finetune_rehearsal},
          {"students", students},
          {"tests", tests}};
}

}  // namespace sc
