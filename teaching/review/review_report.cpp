#include "teaching/review/review_report.hpp"

#include <cstdio>
#include <sstream>

namespace sc::review {
namespace {

std::string skills_text(const std::vector<SkillSpan>& spans) {
  std::string out;
  for (const auto& s : spans) {
    if (!out.empty()) out += ' ';
    out += std::to_string(s.skill);
  }
  return out;
}

Json spans_json(const std::vector<SkillSpan>& spans) {
  Json out = Json::array();
  for (const auto& s : spans)
    out.push_back({{"skill", s.skill}, {"begin", s.begin}, {"end", s.end}, {"description", s.description}});
  return out;
}

std::string number(double v, const char* format = "%.3f") {
  char text[40];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string optional_number(const std::optional<double>& v, const char* format = "%.3f") {
  return v ? number(*v, format) : "";
}

constexpr const char* kStyle = R"(
body{font-family:"DejaVu Sans",Verdana,sans-serif;background:#14181f;color:#e6e9ef;margin:0;padding:24px 40px;line-height:1.45}
h1{font-size:28px;margin:0 0 4px} h2{font-size:22px;margin:36px 0 8px;border-bottom:1px solid #333a47;padding-bottom:6px}
h3{font-size:17px;margin:22px 0 6px;color:#b9d6ff} p.note{color:#9aa5b5;margin:4px 0}
table{border-collapse:collapse;margin:8px 0 16px;font-size:14px} th,td{padding:5px 10px;border-bottom:1px solid #2b3240;text-align:left}
th{color:#9aa5b5;font-weight:600} td.num{text-align:right;font-variant-numeric:tabular-nums}
.good{color:#2ec4b6} .bad{color:#ff8c42}
figure{margin:10px 0 24px;background:#1b2029;padding:10px;border-radius:8px;display:inline-block;max-width:100%}
figure img{max-width:100%;height:auto;display:block;border-radius:4px} figcaption{color:#9aa5b5;font-size:14px;margin-top:6px}
details{margin:6px 0} summary{cursor:pointer;color:#b9d6ff}
)";

void session_header(std::ostringstream& h, const SessionReport& s) {
  const auto& r = s.row;
  h << "<h2>Session " << r.session_id << ": " << html_escape(r.task) << ", " << html_escape(r.condition) << "</h2>\n";
  h << "<table><tr><th>Started</th><th>Finished</th><th>Trials</th><th>Pre-test mean</th><th>Evaluation mean</th>"
       "<th>Improvement</th></tr><tr><td>"
    << html_escape(cell_text(r, SessionColumn::Date)) << "</td><td>" << (r.finished ? "yes" : "not yet")
    << "</td><td class=num>" << r.trial_count << "</td><td class=num>" << cell_text(r, SessionColumn::Pretest)
    << "</td><td class=num>" << cell_text(r, SessionColumn::Evaluation) << "</td><td class=\"num "
    << (r.improvement && *r.improvement > 0 ? "good" : "bad") << "\">" << cell_text(r, SessionColumn::Improvement)
    << "</td></tr></table>\n<p class=note>Scores are the task's reward: 0 is the expert's result, lower is worse; "
       "improvement = evaluation mean - pre-test mean.</p>\n";
}

void image(std::ostringstream& h, const ReportImage& img) {
  h << "<figure><img alt=\"" << html_escape(img.title) << "\" src=\"data:image/png;base64," << base64(img.png_bytes)
    << "\"><figcaption>" << html_escape(img.title) << " (" << html_escape(img.file) << ")</figcaption></figure>\n";
}

void diagnosis_section(std::ostringstream& h, const SessionReport& s) {
  h << "<h3>Diagnosis explained</h3>\n";
  if (!s.extractor_notice.empty()) h << "<p class=note>Skills: " << html_escape(s.extractor_notice) << "</p>\n";
  if (!s.diagnosis) {
    h << "<p class=note>" << html_escape(s.diagnosis_note) << "</p>\n";
    return;
  }
  const auto& d = *s.diagnosis;
  h << "<p class=note>" << (d.mode == ExpertiseMode::Alg2 ? "Alg. 2" : "Quality-aware expertise")
    << " recomputed from the " << d.pretest_trials << " pre-test trials with the " << html_escape(d.extractor)
    << " extractor: a skill the expert used (at position j of its sequence) that the "
       "learner's trial lacks costs &Delta; = &minus;r / j, r the trial's reward"
    << (d.mode == ExpertiseMode::Alg2 ? ". "
                                      : "; one done worse than the learner's other skills (\"done badly\") costs "
                                        "&Delta; = &minus;q / j, q how far that part's execution score falls beyond "
                                        "the learner's usual spread and what noise alone does (for a skill a "
                                        "little off every time, \"a little off\", beyond what noise does to a "
                                        "skill every time). ")
    << (d.learner_hand.empty()
            ? std::string()
            : "The learner's letters follow a hand of their own, closest to " + html_escape(d.learner_hand) +
                  ": each part was also scored against that hand, and q is the better of the two "
                  "scores. ")
    << (d.matches_stored ? "The recomputation matches the stored diagnosis."
                         : "<b>The recomputation differs from the stored diagnosis</b> (the model, the data or the "
                           "diagnosis method changed since).")
    << "</p>\n";
  if (s.hand_picture) image(h, *s.hand_picture);
  h << "<table><tr><th>Targeted skill</th><th>Expertise E</th><th>Used by the expert</th><th>Missed or done "
       "badly in "
       "pre-test trials (&Delta;)</th></tr>\n";
  for (const auto& skill : d.skills) {
    h << "<tr><td>" << skill.skill << ": " << html_escape(skill.description) << "</td><td class=num>"
      << number(skill.expertise) << "</td><td class=num>" << skill.occurrences << "&times;</td><td>";
    if (skill.missed.empty()) h << "none";
    for (std::size_t i = 0; i < skill.missed.size(); ++i) {
      const auto& m = skill.missed[i];
      h << (i ? "; " : "") << "trial " << m.seq
        << (m.repeated    ? " a little off (every time)"
            : m.execution ? " done badly"
                          : "")
        << " (j=" << m.position << (m.execution ? ", q=" : ", r=") << number(m.reward)
        << ", &Delta;=" << number(m.delta) << ")";
    }
    h << "</td></tr>\n";
  }
  h << "</table>\n";
  if (s.places_picture) image(h, *s.places_picture);
}

void trial_table(std::ostringstream& h, const SessionReport& s) {
  h << "<h3>Trials</h3>\n<table><tr><th>#</th><th>Kind</th><th>Round</th><th>Drill</th><th>Score</th><th>Device</th>"
       "<th>Learner's skills</th><th>Expert's / drill's skills</th></tr>\n";
  for (const auto& t : s.trials) {
    const auto& r = t.review.stored.record;
    h << "<tr><td>" << t.review.stored.seq << "</td><td>" << records::to_string(r.kind) << "</td><td class=num>"
      << r.round << "</td><td class=num>" << (r.drill_index ? std::to_string(*r.drill_index + 1) : "")
      << "</td><td class=num>" << optional_number(r.score, "%.2f") << "</td><td>" << html_escape(r.device)
      << "</td><td>" << skills_text(t.review.learner_skills) << "</td><td>"
      << skills_text(t.review.ghost ? t.review.ghost_skills : t.review.expert_skills) << "</td></tr>\n";
  }
  h << "</table>\n";
}

}  // namespace

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += kAlphabet[v >> 6 & 63];
    out += kAlphabet[v & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v =
        static_cast<unsigned char>(bytes[i]) << 16 | (two ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0u);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += two ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

std::string html_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string csv_field(std::string_view text) {
  // A cell starting with = + - @ (or tab/CR) runs as a formula in a spreadsheet, and a device name is
  // whatever the gamepad reports: such text gets a leading apostrophe and quotes (OWASP's CSV injection
  // advice), so it shows as text. Numbers are written elsewhere and keep their minus sign.
  const bool formula = !text.empty() && std::string_view("=+-@\t\r").find(text.front()) != std::string_view::npos;
  if (!formula && text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string out = formula ? "\"'" : "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string trials_csv(const std::vector<SessionReport>& sessions) {
  std::string out =
      "session_id,seq,kind,round,drill_index,task,score,device,started,finished,steps,learner_skills,expert_skills,"
      "ghost_skills,scenario\n";
  for (const auto& s : sessions)
    for (const auto& t : s.trials) {
      const auto& r = t.review.stored.record;
      out += std::to_string(t.session_id) + "," + std::to_string(t.review.stored.seq) + "," +
             std::string(records::to_string(r.kind)) + "," + std::to_string(r.round) + "," +
             (r.drill_index ? std::to_string(*r.drill_index) : "") + "," + csv_field(r.task) + "," +
             optional_number(r.score, "%.6f") + "," + csv_field(r.device) + "," + csv_field(r.started) + "," +
             csv_field(r.finished) + "," + std::to_string(t.review.learner_track.steps()) + "," +
             skills_text(t.review.learner_skills) + "," + skills_text(t.review.expert_skills) + "," +
             skills_text(t.review.ghost_skills) + "," + csv_field(Json::parse(r.scenario_json).dump()) + "\n";
    }
  return out;
}

Json trials_json(const std::string& learner, const std::vector<SessionReport>& sessions) {
  Json trials = Json::array();
  for (const auto& s : sessions)
    for (const auto& t : s.trials) {
      const auto& r = t.review.stored.record;
      trials.push_back({{"session_id", t.session_id},
                        {"seq", t.review.stored.seq},
                        {"kind", records::to_string(r.kind)},
                        {"round", r.round},
                        {"drill_index", r.drill_index ? Json(*r.drill_index) : Json(nullptr)},
                        {"task", r.task},
                        {"score", r.score ? Json(*r.score) : Json(nullptr)},
                        {"device", r.device},
                        {"started", r.started},
                        {"finished", r.finished},
                        {"steps", t.review.learner_track.steps()},
                        {"learner_skills", spans_json(t.review.learner_skills)},
                        {"expert_skills", spans_json(t.review.expert_skills)},
                        {"ghost_skills", spans_json(t.review.ghost_skills)},
                        {"rewards", t.review.rewards},
                        {"scenario", Json::parse(r.scenario_json)},
                        {"trajectory", t.review.learner}});
    }
  return {{"format", "skillcoach-review-trials"}, {"version", 1}, {"learner", learner}, {"trials", std::move(trials)}};
}

std::string report_html(const std::string& learner, const std::vector<SessionReport>& sessions) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8><title>SkillCoach review: " << html_escape(learner)
    << "</title>\n<style>" << kStyle << "</style></head><body>\n<h1>SkillCoach review: " << html_escape(learner)
    << "</h1>\n<p class=note>" << sessions.size() << (sessions.size() == 1 ? " session" : " sessions")
    << ". Every picture is embedded; the same files are next to this page.</p>\n";
  for (const auto& s : sessions) {
    session_header(h, s);
    diagnosis_section(h, s);
    if (s.expertise_chart) {
      h << "<h3>Expertise per skill across rounds</h3>\n";
      image(h, *s.expertise_chart);
    }
    if (!s.before_after.empty()) h << "<h3>Before and after</h3>\n";
    for (const auto& img : s.before_after) image(h, img);
    trial_table(h, s);
    if (!s.trial_images.empty())
      h << "<details><summary>Every trial's picture (" << s.trial_images.size() << ")</summary>\n";
    for (const auto& img : s.trial_images) image(h, img);
    if (!s.trial_images.empty()) h << "</details>\n";
  }
  h << "</body></html>\n";
  return h.str();
}

}  // namespace sc::review
