#pragma once
// study_report.html: one self-contained page (styles inline, the plot embedded as a base64 data URI) with
// the study's definition, the per-condition table, the plot, the tests and every participant, so it can be
// mailed or archived with the data.
#include <string>

#include "teaching/studies/study_analysis.hpp"

namespace sc {

struct StudyReportPlot {
  std::string file;       // the PNG's name next to the page
  std::string png_bytes;  // embedded
};

std::string study_report_html(const StudyAnalysis& analysis, const StudyReportPlot& plot);
// "0.0123", "< 0.0001", "" for NaN: how the page and the console print p-values.
std::string format_p(double p);

}  // namespace sc
