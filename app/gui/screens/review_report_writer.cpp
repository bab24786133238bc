#include "app/gui/screens/review_report_writer.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <memory>
#include <optional>

#include "app/core/review_pictures.hpp"
#include "app/gui/screens/learn_skill_picture.hpp"
#include "engine/core/error.hpp"
#include "engine/render/gl_context.hpp"
#include "teaching/records/open_record_store.hpp"
#include "teaching/review/review_report.hpp"
#include "teaching/review/session_filter.hpp"
#include "teaching/tasks/task_kit_cache.hpp"

namespace sc {
namespace {

namespace fs = std::filesystem;

// The charged targets that say where they went wrong, in the diagnosis' order, drawn from their trial documents as
// the trainer's and the Review's pictures are (a parking path re-simulated at sub-steps).
std::vector<review_view::PlacePicture> place_pictures(const review::DiagnosisExplanation& diagnosis) {
  std::vector<review_view::PlacePicture> out;
  for (const review::SkillExplanation& skill : diagnosis.skills) {
    if (!skill.place) continue;
    const review::SkillPlace& place = *skill.place;
    const std::string trial = " in pre-test trial " + std::to_string(place.seq);
    const std::string what = place.reason == TargetReason::Missing ? "missed" + trial
                             : place.reason == TargetReason::RepeatedError
                                 ? "a little off" + trial + ", as in every trial"
                                 : "done badly" + trial;
    out.push_back({"skill " + std::to_string(skill.skill) + ": " + skill.description + " - " + what,
                   trial_part_picture_data(place)});
  }
  return out;
}

void write_file(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw InputError(file.string(), "cannot be written");
}

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class ReportWriter {
 public:
  ReportWriter(const ReportRequest& request, ReportResult& result) : request_(request), result_(result) {}

  review::ReportImage save(const RgbaImage& image, const std::string& file, const std::string& title) {
    const fs::path path = request_.out / file;
    write_png(path, image);
    result_.files.push_back(path);
    return {title, file, read_file(path)};
  }

  GlContext& context() {
    if (!context_) context_ = create_offscreen_context_from_env(request_.image_width, request_.image_height);
    return *context_;
  }

  review::SessionReport session(const records::RecordStore& store, const review::SessionListRow& row) {
    review::SessionReport report;
    report.row = row;
    review::SessionRecord record = review::load_session_record(store, row.session_id);
    const TaskKit& kit = kits_.kit_of(record.session);
    report.extractor_notice = kit.extractor_notice();
    const review::SessionReview review(kit, std::move(record));
    const std::string where = store.database_path().string() + ": session " + std::to_string(row.session_id);
    std::vector<review::TrialReview> trials;
    for (const auto& t : review.record().trials) {
      try {
        trials.push_back(review.trial(t.seq));
      } catch (const InputError& e) {
        result_.problems.push_back(where + ", trial " + std::to_string(t.seq) + " left out: " + one_line(e.what()));
      }
    }
    const std::string prefix = "session" + std::to_string(row.session_id) + "_";
    // The expertise chart's rounds also give the session's skill colours, so they are read before any picture.
    std::optional<review::ExpertiseRounds> rounds;
    std::string rounds_problem;
    try {
      rounds = review::expertise_rounds(review.kit(), review.record());
    } catch (const InputError& e) {
      rounds_problem = one_line(e.what());
    }
    const review_view::SkillPalette palette = rounds ? session_palette(*rounds) : review_view::SkillPalette{};
    for (const auto& t : trials) {
      report.trials.push_back({row.session_id, t});
      report.trial_images.push_back(
          save(review_view::render_trial_image(context(), trial_picture(t, palette), trial_image_text(row.learner, t),
                                               request_.image_width, request_.image_height),
               prefix + "trial" + std::to_string(t.stored.seq) + ".png", t.label));
    }
    // A damaged row takes out only the picture that reads it; output errors still end the report.
    std::vector<review::BeforeAfterGroup> groups;
    try {
      groups = review::before_after_groups(review.record());
    } catch (const InputError& e) {
      result_.problems.push_back(where + ", before/after pictures left out: " + one_line(e.what()));
    }
    for (const auto& group : groups)
      report.before_after.push_back(save(
          review_view::render_before_after_image(context(), before_after_picture(group, trials),
                                                 "Before / after: " + group.title, before_after_lines(group, trials),
                                                 request_.image_width, request_.image_height),
          prefix + "before_after_" + group.family + ".png", "Before / after: " + group.title));
    if (!rounds_problem.empty()) result_.problems.push_back(where + ", expertise chart left out: " + rounds_problem);
    if (rounds && !rounds->rounds.empty())
      report.expertise_chart =
          save(review_view::render_expertise_chart_image(context(), expertise_chart(*rounds, palette),
                                                         "Expertise per skill across rounds", request_.image_width),
               prefix + "expertise.png", "Expertise per skill across rounds");
    try {
      report.diagnosis = review::explain_diagnosis(review);
    } catch (const InputError& e) {
      report.diagnosis_note = e.what();
    }
    if (report.diagnosis && report.diagnosis->hand_traces)
      report.hand_picture =
          save(review_view::render_hand_image(context(), hand_overlay(*report.diagnosis->hand_traces),
                                              hand_image_text(row.learner, report.diagnosis->learner_hand),
                                              request_.image_width, request_.image_height),
               prefix + "hand.png", "The learner's own hand");
    std::vector<review_view::PlacePicture> places;
    try {
      if (report.diagnosis) places = place_pictures(*report.diagnosis);
    } catch (const InputError& e) {
      result_.problems.push_back(where +
                                 ", the picture of where the targets went wrong left out: " + one_line(e.what()));
    }
    if (!places.empty())
      report.places_picture = save(
          review_view::render_places_image(
              context(), places, row.learner + ": where the targets went wrong",
              {"Each charged target's largest penalty: the pre-test trial it happened in over the expert's trial of "
               "the same scenario, the part aligned with the expert's skill in orange."},
              request_.image_width, request_.image_height),
          prefix + "where.png", "Where the targets went wrong");
    result_.trials += static_cast<int>(trials.size());
    return report;
  }

 private:
  const ReportRequest& request_;
  ReportResult& result_;
  std::unique_ptr<GlContext> context_;
  TaskKitCache kits_;
};

}  // namespace

namespace {

bool started_within(const review::SessionListRow& row, const ReportRequest& request) {
  return review::matches(row, {"", "", request.from, request.to});
}

std::unique_ptr<records::RecordStore> open_for_report(const ReportRequest& request) {
  const records::StoreOptions read_only{.read_only = true};
  if (request.store.empty()) return std::make_unique<records::LearnerStore>(request.data_dir, read_only);
  return records::open_record_store(request.store, read_only);
}

}  // namespace

ReportResult write_learner_report(const ReportRequest& request) {
  const auto opened = open_for_report(request);
  const records::RecordStore& store = *opened;
  const std::vector<std::int64_t> ids = review::learner_session_ids(store, request.learner);
  if (request.session && std::find(ids.begin(), ids.end(), *request.session) == ids.end())
    throw InputError(store.database_path().string(),
                     "learner '" + request.learner + "' has no session " + std::to_string(*request.session));
  std::vector<review::SessionListRow> rows;
  for (const auto& row : review::session_rows(store.list_learners()))
    if (row.learner == request.learner && (!request.session || row.session_id == *request.session) &&
        started_within(row, request))
      rows.push_back(row);

  std::error_code ec;
  fs::create_directories(request.out, ec);
  if (ec) throw InputError(request.out.string(), "cannot create the output folder (" + ec.message() + ")");
  ReportResult result;
  ReportWriter writer(request, result);
  std::vector<review::SessionReport> sessions;
  for (const auto& row : rows) sessions.push_back(writer.session(store, row));
  result.sessions = static_cast<int>(sessions.size());

  const fs::path csv = request.out / "trials.csv", json = request.out / "trials.json",
                 html = request.out / "report.html";
  write_file(csv, review::trials_csv(sessions));
  write_json_file(json, review::trials_json(request.learner, sessions), 1);
  write_file(html, review::report_html(request.learner, sessions));
  result.files.insert(result.files.end(), {csv, json, html});
  return result;
}

}  // namespace sc
