#pragma once
// The tables of `skillcoach study-report`: participants.csv (one row per enrolled participant, counted or
// not, with the reason), conditions.csv (N, mean +- s.e. and quartiles of the reward improvement per
// condition), comparisons.csv (the Mann-Whitney tests with raw and Holm-adjusted p-values) and
// study_report.json (all of it). Numbers are written with full precision (%.17g in CSV); absent values are
// empty cells in CSV and null in JSON. The HTML page is study_report_html.hpp.
#include <string>

#include "engine/core/json_file.hpp"
#include "teaching/studies/study_analysis.hpp"

namespace sc {

inline constexpr std::string_view kStudyReportFormat = "skillcoach-study-report";
inline constexpr int kStudyReportVersion = 1;

std::string participants_csv(const StudyAnalysis& analysis);
std::string conditions_csv(const StudyAnalysis& analysis);
std::string comparisons_csv(const StudyAnalysis& analysis);
Json study_report_json(const StudyAnalysis& analysis);
// One sentence: what the measure is and how the pairs are tested (the report's pages and the docs say it).
std::string study_methods_text(const StudyAnalysis& analysis);

}  // namespace sc
