#include "teaching/students/student_report.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace sc {
namespace {

std::string format(const char* fmt, double a, double b = 0.0) {
  char text[96];
  std::snprintf(text, sizeof text, fmt, a, b);
  return text;
}

// Appends `text` left-aligned in a column of `width` characters plus one space. Appending in place (rather
// than chaining operator+ on temporaries) also avoids GCC 12's false -Wrestrict on string concatenation.
void cell(std::string& out, std::string_view text, std::size_t width) {
  out.append(text);
  if (text.size() < width) out.append(width - text.size(), ' ');
  out.push_back(' ');
}

std::string reward_cell(const std::vector<double>& values) {
  const MeanAndError m = mean_and_standard_error(values);
  return format("%7.4f ± %.4f", m.mean, m.standard_error);
}

std::string success_cell(const std::vector<double>& values) {
  const MeanAndError m = mean_and_standard_error(values);
  return format("%5.1f%% ± %.1f%%", 100.0 * m.mean, 100.0 * m.standard_error);
}

double mean_of(const std::vector<int>& values) {
  double total = 0.0;
  for (int v : values) total += v;
  return values.empty() ? 0.0 : total / static_cast<double>(values.size());
}

Json stats_json(const std::vector<double>& values) {
  const MeanAndError m = mean_and_standard_error(values);
  return {{"mean", m.mean}, {"standard_error", m.standard_error}, {"per_set", values}};
}

}  // namespace

MeanAndError mean_and_standard_error(const std::vector<double>& values) {
  MeanAndError out;
  const double n = static_cast<double>(values.size());
  if (values.empty()) return out;
  for (double v : values) out.mean += v / n;
  if (values.size() < 2) return out;
  double squares = 0.0;
  for (double v : values) squares += (v - out.mean) * (v - out.mean);
  out.standard_error = std::sqrt(squares / (n - 1.0)) / std::sqrt(n);
  return out;
}

std::vector<ConditionComparison> compare_conditions(const StudentExperimentResult& result) {
  const std::pair<StudyCondition, StudyCondition> pairs[] = {
      {StudyCondition::IndDrills, StudyCondition::FullTrajectory},
      {StudyCondition::Drills, StudyCondition::FullTrajectory},
      {StudyCondition::IndDrills, StudyCondition::Drills}};
  std::vector<ConditionComparison> out;
  for (std::size_t s = 0; s < result.students.size(); ++s) {
    for (const auto& [a, b] : pairs) {
      const std::vector<double>& ra = result.students[s].of(a).reward;
      const std::vector<double>& rb = result.students[s].of(b).reward;
      ConditionComparison c{static_cast<int>(s), a, b, 0.0, wilcoxon_signed_rank(ra, rb)};
      for (std::size_t k = 0; k < ra.size(); ++k) c.mean_difference += (ra[k] - rb[k]) / static_cast<double>(ra.size());
      out.push_back(c);
    }
  }
  return out;
}

std::string student_experiment_table(const StudentExperimentResult& result, const TaskKit& kit) {
  const StudentExperimentConfig& c = result.config;
  std::string out;
  out += "Synthetic parking students: " + std::to_string(c.evaluation_sets) + " evaluation sets of ";
  out += std::to_string(c.scenarios_per_set) + " fresh scenarios, mean ± s.e. over sets (seed ";
  out += std::to_string(c.seed) + ")\n";
  out += "skills: " + result.extractor;
  if (!result.extractor_notice.empty()) out += " (" + result.extractor_notice + ")";
  out += "; expert pool " + std::to_string(result.pool_size) + " demos, " + std::to_string(result.expert_pairs);
  out += " pairs, expert score " + format("%.4f", result.expert_pool_reward) + "\n";
  out += "fine-tuning: " + std::to_string(c.finetune_epochs) + " epochs on equal-size data per set";
  if (c.finetune_rehearsal > 0)
    out += ", each condition's data plus " + format("%g", c.finetune_rehearsal) + "x as many of the student's own pairs (rehearsal)";
  out += "\n\n";
  cell(out, "student", 21);
  cell(out, "condition", 16);
  cell(out, "reward (last step)", 19);
  cell(out, "success", 16);
  out += "pairs  reverse\n";
  for (const StudentResult& s : result.students) {
    cell(out, student_name(s.recipe.kind), 21);
    cell(out, "before", 16);
    cell(out, reward_cell(s.before_reward), 19);
    cell(out, success_cell(s.before_success), 16);
    out += "\n";
    for (const ConditionResult& r : s.conditions) {
      cell(out, "", 21);
      cell(out, condition_name(r.condition), 16);
      cell(out, reward_cell(r.reward), 19);
      cell(out, success_cell(r.success), 16);
      out += format("%5.1f  %5.1f", mean_of(r.pairs), mean_of(r.reverse_pairs)) + "\n";
    }
  }
  out += "\nweakest skills (Alg. 2 on the student's rollouts of " + std::to_string(result.diagnosis_scenarios.size());
  out += " diverse pool scenarios):\n";
  for (const StudentResult& s : result.students) {
    out += "  ";
    cell(out, student_name(s.recipe.kind), 21);
    out += format("score %.4f, success %.0f%%:", s.diagnosis_reward, 100.0 * s.diagnosis_success);
    for (int m : s.diagnosis.targets) {
      out += ' ';
      out += std::to_string(m);
      out += " (";
      out += kit.describe_skill(m);
      out += format(", E %.3f)", s.diagnosis.expertise[static_cast<std::size_t>(m)]);
    }
    out += "\n";
  }
  out += "\nWilcoxon signed-rank tests on the per-set mean reward (two-sided, paired by set):\n";
  for (const ConditionComparison& cmp : compare_conditions(result)) {
    out += "  ";
    cell(out, student_name(result.students[static_cast<std::size_t>(cmp.student)].recipe.kind), 21);
    std::string pair(condition_name(cmp.a));
    pair += " vs ";
    pair += condition_name(cmp.b);
    cell(out, pair, 32);
    out += format("diff %+.4f  ", cmp.mean_difference);
    out += format("W+ %5.1f  W- %5.1f  ", cmp.test.w_plus, cmp.test.w_minus);
    out += format("p = %.4f", cmp.test.p_two_sided);
    out += cmp.test.p_two_sided < 0.05 ? " *\n" : "\n";
  }
  return out;
}

Json student_experiment_json(const StudentExperimentResult& result, const TaskKit& kit) {
  const StudentExperimentConfig& c = result.config;
  Json doc = {{"seed", c.seed},
              {"extractor", result.extractor},
              {"extractor_notice", result.extractor_notice},
              {"expert_pool", {{"demos", result.pool_size}, {"pairs", result.expert_pairs}, {"mean_score", result.expert_pool_reward}}},
              {"diagnosis_scenarios", result.diagnosis_scenarios},
              {"config", {{"diagnosis_scenarios", c.diagnosis_scenarios}, {"num_targets", c.num_targets},
                          {"finetune_epochs", c.finetune_epochs}, {"finetune_pairs", c.finetune_pairs},
                          {"finetune_rehearsal", c.finetune_rehearsal},
                          {"evaluation_sets", c.evaluation_sets}, {"scenarios_per_set", c.scenarios_per_set}}}};
  Json students = Json::array();
  for (const StudentResult& s : result.students) {
    Json targets = Json::array();
    for (int m : s.diagnosis.targets)
      targets.push_back({{"skill", m}, {"expertise", s.diagnosis.expertise[static_cast<std::size_t>(m)]},
                         {"description", kit.describe_skill(m)}});
    Json conditions = Json::array();
    for (const ConditionResult& r : s.conditions)
      conditions.push_back({{"condition", condition_name(r.condition)}, {"key", condition_key(r.condition)},
                            {"reward", stats_json(r.reward)}, {"success", stats_json(r.success)},
                            {"pairs", r.pairs}, {"reverse_pairs", r.reverse_pairs}, {"rehearsal_pairs", r.rehearsal_pairs},
                            {"finetune_loss", r.finetune_loss}});
    students.push_back({{"student", student_name(s.recipe.kind)}, {"key", student_key(s.recipe.kind)},
                        {"epochs", s.recipe.epochs}, {"reverse_keep_fraction", s.recipe.reverse_keep_fraction},
                        {"hidden", s.recipe.hidden}, {"training_pairs", s.training_pairs},
                        {"reverse_pairs_total", s.reverse_pairs_total}, {"reverse_pairs_kept", s.reverse_pairs_kept},
                        {"training_loss", s.training_loss}, {"expert_mse", s.expert_mse},
                        {"diagnosis", {{"mean_score", s.diagnosis_reward}, {"success", s.diagnosis_success},
                                       {"expertise", s.diagnosis.expertise}, {"ranking", s.diagnosis.ranking},
                                       {"targets", std::move(targets)}}},
                        {"before", {{"reward", stats_json(s.before_reward)}, {"success", stats_json(s.before_success)}}},
                        {"conditions", std::move(conditions)}});
  }
  doc["students"] = std::move(students);
  Json tests = Json::array();
  for (const ConditionComparison& cmp : compare_conditions(result))
    tests.push_back({{"student", student_name(result.students[static_cast<std::size_t>(cmp.student)].recipe.kind)},
                     {"a", condition_name(cmp.a)}, {"b", condition_name(cmp.b)}, {"mean_difference", cmp.mean_difference},
                     {"n", cmp.test.n}, {"w_plus", cmp.test.w_plus}, {"w_minus", cmp.test.w_minus},
                     {"p_two_sided", cmp.test.p_two_sided}, {"exact", cmp.test.exact}});
  doc["wilcoxon"] = std::move(tests);
  return doc;
}

}  // namespace sc
