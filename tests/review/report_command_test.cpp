// `skillcoach report` (app/cli/report_command.cpp) on the review's database fixture: the expected files with
// the expected content, the database untouched, and one-line errors with exit code 2 for an unknown learner
// or session and for a damaged database.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "engine/render/rgba_image.hpp"
#include "teaching/records/sqlite_handle.hpp"
#include "teaching/review/before_after.hpp"
#include "teaching/review/diagnosis_explained.hpp"
#include "tests/review/review_fixture.hpp"
#include "tests/support/run_skillcoach.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& p) {
  std::string out(1, '\'');
  out += p.string();
  out += '\'';
  return out;
}

// The database and its log, byte for byte.
std::string database_bytes(const fs::path& dir) {
  std::string bytes;
  for (const char* name : {"skillcoach.db", "skillcoach.db-wal"})
    if (fs::exists(dir / name)) bytes += test::read_bytes(dir / name);
  return bytes;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class ReportCommand : public ::testing::Test {
 protected:
  const test::ReviewFixture& fixture = test::parking_review_fixture();
  records::LearnerStore store{fixture.data_dir, records::StoreOptions{.read_only = true}};
};

TEST_F(ReportCommand, WritesEveryPictureTheTablesAndASelfContainedPage) {
  const fs::path out = test::scratch_path("review", "report_all");
  fs::remove_all(out);
  const std::string before = database_bytes(fixture.data_dir);
  const test::CommandResult run =
      test::run_skillcoach("report --data-dir " + quoted(fixture.data_dir) + " --learner Ada --out " + quoted(out));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(database_bytes(fixture.data_dir), before);

  const auto trials = store.trials_of_session(fixture.session_id);
  const std::string prefix = "session" + std::to_string(fixture.session_id) + "_";
  std::set<std::string> pngs;
  for (const auto& t : trials) pngs.insert(prefix + "trial" + std::to_string(t.seq) + ".png");
  pngs.insert(prefix + "expertise.png");
  for (const auto& g : review::before_after_groups(review::load_session_record(store, fixture.session_id)))
    pngs.insert(prefix + "before_after_" + g.family + ".png");
  // The fixture's diagnosis charges a target, so the report pictures where (beside the diagnosis table).
  const review::SessionReview review(test::parking_kit(), review::load_session_record(store, fixture.session_id));
  const review::DiagnosisExplanation diagnosis = review::explain_diagnosis(review);
  ASSERT_TRUE(std::any_of(diagnosis.skills.begin(), diagnosis.skills.end(), [](const auto& s) { return s.place; }));
  pngs.insert(prefix + "where.png");
  std::set<std::string> written;
  for (const auto& entry : fs::directory_iterator(out)) written.insert(entry.path().filename().string());
  std::set<std::string> expected = pngs;
  expected.insert({"trials.csv", "trials.json", "report.html"});
  EXPECT_EQ(written, expected);
  for (const auto& png : pngs) {
    const RgbaImage image = read_png(out / png);
    EXPECT_EQ(image.width, 1280) << png;
    EXPECT_GE(image.height, 720) << png;
  }

  // trials.csv: a header and one line per trial, in seq order with its kind and score.
  std::istringstream csv(test::read_bytes(out / "trials.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("session_id,seq,kind,round,drill_index,task,score,", 0), 0u);
  for (const auto& t : trials) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::string start = std::to_string(fixture.session_id) + "," + std::to_string(t.seq) + "," +
                              std::string(records::to_string(t.record.kind)) + ",";
    EXPECT_EQ(line.rfind(start, 0), 0u) << line;
  }
  EXPECT_FALSE(std::getline(csv, line));

  // trials.json: every trial with its stored score and its whole trajectory document.
  const Json doc = Json::parse(test::read_bytes(out / "trials.json"));
  EXPECT_EQ(doc.at("format"), "skillcoach-review-trials");
  ASSERT_EQ(doc.at("trials").size(), trials.size());
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const Json& t = doc.at("trials")[i];
    EXPECT_EQ(t.at("seq"), trials[i].seq);
    EXPECT_EQ(t.at("trajectory"), Json::parse(trials[i].record.trajectory_json));
    if (trials[i].record.score) {
      EXPECT_DOUBLE_EQ(t.at("score").get<double>(), *trials[i].record.score);
    }
    EXPECT_FALSE(t.at("learner_skills").empty());
  }

  // report.html: every picture embedded, nothing fetched from elsewhere, the diagnosis explained.
  const std::string html = test::read_bytes(out / "report.html");
  EXPECT_EQ(count(html, "src=\"data:image/png;base64,"), pngs.size());
  EXPECT_EQ(count(html, "src=\"http"), 0u);
  EXPECT_EQ(count(html, "<link"), 0u);
  EXPECT_NE(html.find("SkillCoach review: Ada"), std::string::npos);
  EXPECT_NE(html.find("The recomputation matches the stored diagnosis."), std::string::npos);
  EXPECT_NE(html.find("Missed or done badly in pre-test trials"), std::string::npos);
  const auto table = html.find("<th>Targeted skill</th>"), where = html.find("(" + prefix + "where.png)");
  ASSERT_NE(where, std::string::npos);
  EXPECT_LT(table, where);
  EXPECT_LT(where, html.find("(" + prefix + "expertise.png)"));
}

// A writing learner in unseen drawer 13's letters is given a training drawer's hand; the report pictures its first
// pre-test word over the guide and over that hand beside the diagnosis, as the Review screen does. The parking
// fixture above takes no hand, so its report has no such picture.
TEST(ReportCommandHand, AWritingLearnerInAHandOfItsOwnHasTheHandPictured) {
  const fs::path data = test::scratch_path("review", "report_hand_data"),
                 out = test::scratch_path("review", "report_hand");
  fs::remove_all(data);
  fs::remove_all(out);
  const test::CommandResult learn = test::run_skillcoach(
      "learn --task writing --pretest 3 --eval 2 --learner-hand 13 --learner Ada --data-dir " + quoted(data));
  ASSERT_EQ(learn.exit_code, 0) << learn.output;
  const auto hand_line = learn.output.find("  learner's hand: ");
  ASSERT_NE(hand_line, std::string::npos) << learn.output;
  const std::string hand =
      learn.output.substr(hand_line + 18, learn.output.find('\n', hand_line) - hand_line - 18);  // "the letters of ..."

  const test::CommandResult run =
      test::run_skillcoach("report --data-dir " + quoted(data) + " --learner Ada --out " + quoted(out));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const RgbaImage image = read_png(out / "session1_hand.png");
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 720);
  const std::string html = test::read_bytes(out / "report.html");
  const auto diagnosis = html.find("<h3>Diagnosis explained</h3>"), picture = html.find("(session1_hand.png)");
  ASSERT_NE(picture, std::string::npos);
  EXPECT_LT(diagnosis, picture);
  EXPECT_LT(picture, html.find("<th>Targeted skill</th>"));  // beside the sentence naming the hand, above the table
  EXPECT_NE(html.find("closest to " + hand), std::string::npos) << hand;
}

TEST_F(ReportCommand, OneSessionOnly) {
  const fs::path out = test::scratch_path("review", "report_one");
  fs::remove_all(out);
  const test::CommandResult run =
      test::run_skillcoach("report --data-dir " + quoted(fixture.data_dir) + " --learner Ada --session " +
                           std::to_string(fixture.session_id) + " --out " + quoted(out));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_NE(run.output.find("1 session(s)"), std::string::npos) << run.output;
}

// The fixture's session started on 2024-05-01: --from/--to are inclusive date prefixes.
TEST_F(ReportCommand, DateRangeKeepsTheSessionsStartedWithinIt) {
  const fs::path out = test::scratch_path("review", "report_dates");
  const std::string base = "report --data-dir " + quoted(fixture.data_dir) + " --learner Ada --out " + quoted(out);
  fs::remove_all(out);
  test::CommandResult run = test::run_skillcoach(base + " --from 2024-05-01 --to 2024-05-01");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("1 session(s)"), std::string::npos) << run.output;
  fs::remove_all(out);
  run = test::run_skillcoach(base + " --from 2024-05-02");
  EXPECT_NE(run.output.find("0 session(s)"), std::string::npos) << run.output;
  // A bound that is not a date is refused, not silently ignored (it would report every session).
  run = test::run_skillcoach(base + " --to 2024-13-01");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("not an ISO date"), std::string::npos) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
}

TEST_F(ReportCommand, UnknownLearnerOrSessionIsOneLineAndExitCode2) {
  const fs::path out = test::scratch_path("review", "report_unknown");
  fs::remove_all(out);
  const std::string db = (fixture.data_dir / "skillcoach.db").string();
  test::CommandResult run =
      test::run_skillcoach("report --data-dir " + quoted(fixture.data_dir) + " --learner Bob --out " + quoted(out));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.output, "skillcoach: error: " + db + ": has no learner 'Bob' (learners: Ada)\n");
  run = test::run_skillcoach("report --data-dir " + quoted(fixture.data_dir) + " --learner Ada --session 99 --out " +
                             quoted(out));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.output, "skillcoach: error: " + db + ": learner 'Ada' has no session 99\n");
  EXPECT_FALSE(fs::exists(out));  // nothing is written for a request that cannot be met
}

// One damaged stored trial: the rest of the report is written, the bad row named on one line, exit 2.
TEST_F(ReportCommand, ADamagedTrialIsNamedAndTheRestReported) {
  const fs::path dir = test::scratch_path("review", "report_damaged_row");
  fs::remove_all(dir);
  fs::create_directories(dir / "data");
  for (const char* name : {"skillcoach.db", "skillcoach.db-wal"})
    if (fs::exists(fixture.data_dir / name)) fs::copy_file(fixture.data_dir / name, dir / "data" / name);
  {
    records::SqliteDb raw(dir / "data" / "skillcoach.db", records::SqliteDb::Mode::ReadWriteCreate);
    raw.exec("UPDATE trials SET trajectory = json_remove(trajectory, '$.scenario') WHERE seq = 2");
  }
  const test::CommandResult run =
      test::run_skillcoach("report --data-dir " + quoted(dir / "data") + " --learner Ada --out " + quoted(dir / "out"));
  EXPECT_EQ(run.exit_code, 2) << run.output;
  const std::string named = "skillcoach: error: " + (dir / "data" / "skillcoach.db").string() + ": session " +
                            std::to_string(fixture.session_id) + ", trial 2 left out: ";
  EXPECT_NE(run.output.find(named), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("scenario"), std::string::npos) << run.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "report.html"));
  const std::string prefix = "session" + std::to_string(fixture.session_id) + "_";
  EXPECT_TRUE(fs::exists(dir / "out" / (prefix + "trial1.png")));
  EXPECT_FALSE(fs::exists(dir / "out" / (prefix + "trial2.png")));
  const std::string csv = test::read_bytes(dir / "out" / "trials.csv");
  const auto trials = store.trials_of_session(fixture.session_id);
  EXPECT_EQ(count(csv, "\n"), trials.size());  // the header and every trial but the damaged one
}

TEST_F(ReportCommand, DamagedOrMissingDatabaseIsRefusedAndLeftAlone) {
  const fs::path dir = test::scratch_path("review", "report_damaged");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string garbage(4096, 'x');
  test::write_bytes(dir / "skillcoach.db", garbage);
  test::CommandResult run =
      test::run_skillcoach("report --data-dir " + quoted(dir) + " --learner Ada --out " + quoted(dir / "out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(count(run.output, "\n"), 1u) << run.output;
  EXPECT_NE(run.output.find((dir / "skillcoach.db").string()), std::string::npos) << run.output;
  EXPECT_EQ(test::read_bytes(dir / "skillcoach.db"), garbage);
  EXPECT_FALSE(fs::exists(dir / "out"));

  const fs::path empty = test::scratch_path("review", "report_missing");
  fs::remove_all(empty);
  fs::create_directories(empty);
  run = test::run_skillcoach("report --data-dir " + quoted(empty) + " --learner Ada --out " + quoted(empty / "out"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("no such database"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(empty / "skillcoach.db"));  // the report never creates a database
}

}  // namespace
}  // namespace sc
