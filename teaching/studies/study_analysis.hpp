#pragma once
// A study's result, as the paper reports its human study: per condition the reward improvement's
// mean +- standard error and N (participants counted; study_outcomes.hpp says which), and between
// conditions the two-sided Mann-Whitney U test (teaching/stats/mann_whitney.hpp) of the planned pairs
// (study_comparisons.hpp), Holm-corrected over the pairs tested (teaching/stats/holm_correction.hpp).
#include <optional>
#include <string>
#include <vector>

#include "teaching/records/study_records.hpp"
#include "teaching/stats/mann_whitney.hpp"
#include "teaching/stats/sample_summary.hpp"
#include "teaching/studies/study_comparisons.hpp"
#include "teaching/studies/study_outcomes.hpp"

namespace sc {

struct StudyConditionResult {
  std::string condition;  // key, as stored
  std::string name;       // as the paper prints it ("Time Heuristic")
  int enrolled = 0;
  int target = 0;
  std::vector<double> improvements;    // of the counted participants, in enrolment order
  stats::SampleSummary improvement;    // of `improvements`; improvement.n is the condition's N
  stats::SampleSummary pretest, eval;  // the counted participants' mean pre-test and evaluation rewards
};

struct StudyConditionComparison {
  std::string a, b;  // condition keys; U is a's
  int n_a = 0, n_b = 0;
  double mean_difference = 0.0;                  // mean improvement of a - of b (NaN when one is empty)
  std::optional<stats::MannWhitneyResult> test;  // none when a condition has no counted participant
  double p_holm = 0.0;                           // Holm-adjusted over the pairs tested (NaN when not tested)
  bool significant = false;                      // p_holm <= alpha
};

struct StudyAnalysis {
  records::StudyDefinition study;
  std::vector<ParticipantOutcome> participants;       // enrolment order, counted or not
  std::vector<StudyConditionResult> conditions;       // the study's condition order
  std::vector<StudyConditionComparison> comparisons;  // planned order
  ComparisonPlan plan = ComparisonPlan::Paper;
  double alpha = 0.05;
  int counted() const;
};

StudyAnalysis analyse_study(const records::StudyDefinition& study, std::vector<ParticipantOutcome> participants,
                            ComparisonPlan plan = ComparisonPlan::Paper, double alpha = 0.05);
// The paper's name of a condition key ("ind-drills" -> "Ind. Drills"); an unknown key is returned as it is.
std::string condition_display_name(const std::string& key);

}  // namespace sc
