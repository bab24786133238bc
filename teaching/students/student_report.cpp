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

double mean_mse(const std::vector<SplitMse>& values, bool reverse) {
  double total = 0.0;
  for (const SplitMse& m : values) total += reverse ? m.reverse : m.forward;
  return values.empty() ? 0.0 : total / static_cast<double>(values.size());
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

double mean_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double total = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) total += a[k] - b[k];
  return a.empty() ? 0.0 : total / static_cast<double>(a.size());
}

std::string header_lines(const StudentExperimentResult& result) {
  const StudentExperimentConfig& c = result.config;
  std::string out = "Synthetic parking students: " + std::to_string(c.evaluation_sets) + " evaluation sets of ";
  out += std::to_string(c.scenarios_per_set) + " fresh scenarios (goals: " + std::string(to_string(c.region));
  out += "), mean ± s.e. over sets (seed " + std::to_string(c.seed) + ")\n";
  out += "skills: " + result.extractor;
  if (!result.extractor_notice.empty()) out += " (" + result.extractor_notice + ")";
  out += "; teaching pool " + std::to_string(result.pool_size) + " demos, " + std::to_string(result.expert_pairs);
  out += " pairs, expert score " + format("%.4f", result.expert_pool_reward) + "\n";
  out += "students cloned on " + std::to_string(c.student_drives) + " other expert drives (" +
         std::to_string(result.student_pairs) + " pairs); measured on " + std::to_string(c.heldout_drives) +
         " held-out drives (" + std::to_string(result.heldout_pairs) + " pairs)\n";
  out += "fine-tuning: " + std::to_string(c.finetune_epochs) + " epochs at lr " +
         format("%g", c.finetune_learning_rate) + " on equal-size data per set";
  if (c.finetune_pairs > 0) out += " (" + std::to_string(c.finetune_pairs) + " pairs)";
  if (c.finetune_rehearsal > 0)
    out += ", each condition's data plus " + format("%g", c.finetune_rehearsal) +
           "x as many of the student's own pairs (rehearsal)";
  return out + "\n";
}

void student_line(std::string& out, const StudentResult& s) {
  cell(out, student_name(s.recipe.kind), 21);
  out += format("%4.0f  %4.2f  ", s.recipe.epochs, s.recipe.reverse_keep_fraction);
  out += format("%6.0f  ", s.training_pairs);
  out += format("%.4f  %.4f", s.heldout_mse.all, s.heldout_mse.reverse);
  out += format("  %.4f   ", s.heldout_mse.forward);
  out += format("%5.1f%%   %7.4f", 100.0 * s.heldout.success_rate, s.heldout.mean_reward);
  out += format("   %7.4f\n", s.heldout.step_reward);
}

std::string students_lines(const StudentExperimentResult& result) {
  std::string out =
      "\nstudent               epochs keep  pairs   held-out MSE: all / reverse / forward   "
      "success  last-step  per-step\n";
  student_line(out, result.reference);
  for (const StudentResult& s : result.students) student_line(out, s);
  cell(out, "expert planner", 21);
  out += std::string(52, ' ');
  out += format("%5.1f%%   %7.4f", 100.0 * result.expert_heldout.success_rate, result.expert_heldout.mean_reward);
  out += format("   %7.4f\n", result.expert_heldout.step_reward);
  return out;
}

std::string diagnosis_lines(const StudentExperimentResult& result, const TaskKit& kit) {
  std::string out = "\nweakest skills (Alg. 2 on the student's rollouts of " +
                    std::to_string(result.diagnosis_scenarios.size()) + " diverse pool scenarios):\n";
  auto line = [&](const StudentResult& s) {
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
  };
  line(result.reference);
  for (const StudentResult& s : result.students) line(s);
  return out;
}

std::string comparison_lines(const StudentExperimentResult& result) {
  std::string out =
      "\nWilcoxon signed-rank tests, paired by set (two-sided; * p < .05): last-step reward | per-step reward | "
      "success\n";
  for (const ConditionComparison& cmp : compare_conditions(result)) {
    out += "  ";
    cell(out, student_name(result.students[static_cast<std::size_t>(cmp.student)].recipe.kind), 21);
    std::string pair(condition_name(cmp.a));
    pair += " vs ";
    pair += condition_name(cmp.b);
    cell(out, pair, 32);
    out += format("%+.4f p = %.4f", cmp.mean_difference, cmp.test.p_two_sided);
    out += cmp.test.p_two_sided < 0.05 ? "* | " : "  | ";
    out += format("%+.4f p = %.4f", cmp.step_difference, cmp.step_test.p_two_sided);
    out += cmp.step_test.p_two_sided < 0.05 ? "* | " : "  | ";
    out += format("%+.1f%%\n", 100.0 * cmp.success_difference);
  }
  return out;
}

std::string curve_lines(const StudentExperimentResult& result) {
  if (!result.curve) return "";
  const LearningCurve& c = *result.curve;
  std::string out = "\nlearning curve: reversing difficulty fine-tuned on a fixed set of 3 Ind. Drills (" +
                    std::to_string(c.drill_pairs) + " pairs, " + std::to_string(c.reverse_pairs) + " reversing";
  if (c.rehearsal_pairs > 0) out += ", + " + std::to_string(c.rehearsal_pairs) + " of its own";
  out += "), " + std::to_string(result.config.curve.rollouts) + " rollouts per point\n";
  out += "  epochs  reward (last step)  reward (per step)  success\n";
  for (const LearningCurvePoint& p : c.points)
    out += format("  %6.0f", p.epochs) + format("  %18.4f", p.score.mean_reward) +
           format("  %17.4f", p.score.step_reward) + format("  %6.1f%%\n", 100.0 * p.score.success_rate);
  out += "  expert" + format("  %18.4f", c.expert.mean_reward) + format("  %17.4f", c.expert.step_reward) +
         format("  %6.1f%%\n", 100.0 * c.expert.success_rate);
  return out;
}

Json score_json(const ParkingScore& score) {
  return {{"mean_score", score.mean_reward}, {"step_reward", score.step_reward}, {"success", score.success_rate}};
}

Json student_json(const StudentResult& s, const TaskKit& kit) {
  Json targets = Json::array();
  for (int m : s.diagnosis.targets)
    targets.push_back({{"skill", m},
                       {"expertise", s.diagnosis.expertise[static_cast<std::size_t>(m)]},
                       {"description", kit.describe_skill(m)}});
  Json conditions = Json::array();
  for (const ConditionResult& r : s.conditions)
    conditions.push_back({{"condition", condition_name(r.condition)},
                          {"key", condition_key(r.condition)},
                          {"reward", stats_json(r.reward)},
                          {"step_reward", stats_json(r.step_reward)},
                          {"success", stats_json(r.success)},
                          {"pairs", r.pairs},
                          {"reverse_pairs", r.reverse_pairs},
                          {"rehearsal_pairs", r.rehearsal_pairs},
                          {"finetune_loss", r.finetune_loss},
                          {"heldout_mse_reverse", mean_mse(r.heldout_mse, true)},
                          {"heldout_mse_forward", mean_mse(r.heldout_mse, false)}});
  return {{"student", student_name(s.recipe.kind)},
          {"key", student_key(s.recipe.kind)},
          {"epochs", s.recipe.epochs},
          {"reverse_keep_fraction", s.recipe.reverse_keep_fraction},
          {"hidden", s.recipe.hidden},
          {"training_pairs", s.training_pairs},
          {"reverse_pairs_total", s.reverse_pairs_total},
          {"reverse_pairs_kept", s.reverse_pairs_kept},
          {"training_loss", s.training_loss},
          {"training_mse", s.expert_mse},
          {"heldout",
           {{"mse", s.heldout_mse.all},
            {"mse_reverse", s.heldout_mse.reverse},
            {"mse_forward", s.heldout_mse.forward},
            {"driving", score_json(s.heldout)}}},
          {"diagnosis",
           {{"mean_score", s.diagnosis_reward},
            {"success", s.diagnosis_success},
            {"expertise", s.diagnosis.expertise},
            {"ranking", s.diagnosis.ranking},
            {"targets", std::move(targets)}}},
          {"before",
           {{"reward", stats_json(s.before_reward)},
            {"step_reward", stats_json(s.before_step_reward)},
            {"success", stats_json(s.before_success)}}},
          {"conditions", std::move(conditions)}};
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
      const ConditionResult& ca = result.students[s].of(a);
      const ConditionResult& cb = result.students[s].of(b);
      ConditionComparison c{static_cast<int>(s),
                            a,
                            b,
                            mean_difference(ca.reward, cb.reward),
                            wilcoxon_signed_rank(ca.reward, cb.reward),
                            mean_difference(ca.step_reward, cb.step_reward),
                            wilcoxon_signed_rank(ca.step_reward, cb.step_reward),
                            mean_difference(ca.success, cb.success)};
      out.push_back(c);
    }
  }
  return out;
}

std::string student_experiment_table(const StudentExperimentResult& result, const TaskKit& kit) {
  std::string out = header_lines(result);
  out += students_lines(result);
  out += "\n";
  cell(out, "student", 21);
  cell(out, "condition", 16);
  cell(out, "reward (last step)", 19);
  cell(out, "reward (per step)", 19);
  cell(out, "success", 16);
  out += "pairs  reverse  held-out MSE reverse / forward\n";
  for (const StudentResult& s : result.students) {
    cell(out, student_name(s.recipe.kind), 21);
    cell(out, "before", 16);
    cell(out, reward_cell(s.before_reward), 19);
    cell(out, reward_cell(s.before_step_reward), 19);
    cell(out, success_cell(s.before_success), 16);
    out += format("               %.4f / %.4f\n", s.heldout_mse.reverse, s.heldout_mse.forward);
    for (const ConditionResult& r : s.conditions) {
      cell(out, "", 21);
      cell(out, condition_name(r.condition), 16);
      cell(out, reward_cell(r.reward), 19);
      cell(out, reward_cell(r.step_reward), 19);
      cell(out, success_cell(r.success), 16);
      out += format("%5.1f  %5.1f", mean_of(r.pairs), mean_of(r.reverse_pairs));
      out += format("    %.4f / %.4f\n", mean_mse(r.heldout_mse, true), mean_mse(r.heldout_mse, false));
    }
  }
  out += diagnosis_lines(result, kit);
  out += comparison_lines(result);
  out += curve_lines(result);
  return out;
}

Json student_experiment_json(const StudentExperimentResult& result, const TaskKit& kit) {
  const StudentExperimentConfig& c = result.config;
  Json doc = {
      {"seed", c.seed},
      {"extractor", result.extractor},
      {"extractor_notice", result.extractor_notice},
      {"expert_pool",
       {{"demos", result.pool_size}, {"pairs", result.expert_pairs}, {"mean_score", result.expert_pool_reward}}},
      {"student_drives", {{"drives", c.student_drives}, {"pairs", result.student_pairs}}},
      {"heldout_drives",
       {{"drives", c.heldout_drives}, {"pairs", result.heldout_pairs}, {"expert", score_json(result.expert_heldout)}}},
      {"diagnosis_scenarios", result.diagnosis_scenarios},
      {"config",
       {{"diagnosis_scenarios", c.diagnosis_scenarios},
        {"num_targets", c.num_targets},
        {"region", to_string(c.region)},
        {"finetune_epochs", c.finetune_epochs},
        {"finetune_learning_rate", c.finetune_learning_rate},
        {"finetune_pairs", c.finetune_pairs},
        {"finetune_rehearsal", c.finetune_rehearsal},
        {"evaluation_sets", c.evaluation_sets},
        {"scenarios_per_set", c.scenarios_per_set}}}};
  doc["reference"] = student_json(result.reference, kit);
  Json students = Json::array();
  for (const StudentResult& s : result.students) students.push_back(student_json(s, kit));
  doc["students"] = std::move(students);
  Json tests = Json::array();
  for (const ConditionComparison& cmp : compare_conditions(result))
    tests.push_back({{"student", student_name(result.students[static_cast<std::size_t>(cmp.student)].recipe.kind)},
                     {"a", condition_name(cmp.a)},
                     {"b", condition_name(cmp.b)},
                     {"mean_difference", cmp.mean_difference},
                     {"n", cmp.test.n},
                     {"w_plus", cmp.test.w_plus},
                     {"w_minus", cmp.test.w_minus},
                     {"p_two_sided", cmp.test.p_two_sided},
                     {"exact", cmp.test.exact},
                     {"step_reward",
                      {{"mean_difference", cmp.step_difference},
                       {"w_plus", cmp.step_test.w_plus},
                       {"w_minus", cmp.step_test.w_minus},
                       {"p_two_sided", cmp.step_test.p_two_sided}}},
                     {"success_difference", cmp.success_difference}});
  doc["wilcoxon"] = std::move(tests);
  if (result.curve) {
    Json points = Json::array();
    for (const LearningCurvePoint& p : result.curve->points)
      points.push_back({{"epochs", p.epochs}, {"loss", p.loss}, {"score", score_json(p.score)}});
    doc["learning_curve"] = {{"student", "reversing difficulty"},
                             {"rollouts", c.curve.rollouts},
                             {"drill_pairs", result.curve->drill_pairs},
                             {"reverse_pairs", result.curve->reverse_pairs},
                             {"rehearsal_pairs", result.curve->rehearsal_pairs},
                             {"expert", score_json(result.curve->expert)},
                             {"points", std::move(points)}};
  }
  return doc;
}

}  // namespace sc
