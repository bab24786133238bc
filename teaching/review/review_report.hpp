#pragma once
// The files of `skillcoach report` that are not pictures: trials.csv and trials.json (one entry per trial,
// with both segmentations and, in the JSON, the trajectory document itself) and report.html, a single
// self-contained page (styles inline, pictures embedded as base64 data URIs) that an instructor can mail
// or open offline. The pictures are rendered by the caller (engine/review_view) and passed in as PNG bytes.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "engine/core/json_file.hpp"
#include "teaching/review/diagnosis_explained.hpp"
#include "teaching/review/session_rows.hpp"
#include "teaching/review/trial_review.hpp"

namespace sc::review {

struct ReportTrial {
  std::int64_t session_id = 0;
  TrialReview review;
};

struct ReportImage {
  std::string title;
  std::string file;       // the PNG's name next to report.html
  std::string png_bytes;  // embedded in the HTML
};

struct SessionReport {
  SessionListRow row;
  std::vector<ReportTrial> trials;
  std::optional<DiagnosisExplanation> diagnosis;  // none when the session has no diagnosis yet
  std::string diagnosis_note;                     // why there is none
  std::string extractor_notice;                   // the kit's fallback notice (e.g. no trained model), if any
  std::optional<ReportImage> hand_picture;        // the diagnosis took a hand of the learner's own (writing)
  std::optional<ReportImage> places_picture;      // where the charged targets went wrong (SkillExplanation::place)
  std::optional<ReportImage> expertise_chart;
  std::vector<ReportImage> before_after;
  std::vector<ReportImage> trial_images;  // one per trial, in seq order
};

// Header and one line per trial: session_id,seq,kind,round,drill_index,task,score,device,started,finished,
// steps,learner_skills,expert_skills,ghost_skills,scenario (skills as space-separated ids; RFC 4180 quoting).
std::string trials_csv(const std::vector<SessionReport>& sessions);
Json trials_json(const std::string& learner, const std::vector<SessionReport>& sessions);
std::string report_html(const std::string& learner, const std::vector<SessionReport>& sessions);

std::string base64(std::string_view bytes);
std::string html_escape(std::string_view text);
// RFC 4180 quoting; text a spreadsheet would run as a formula is neutralised with a leading apostrophe.
std::string csv_field(std::string_view text);

}  // namespace sc::review
