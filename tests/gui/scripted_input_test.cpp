// End-to-end runs through the trainer's real screens: `skillcoach --script FILE.json` opens the window on
// SDL's offscreen driver and a scripted learner (tests/gui/data/*_session.json) clicks, types, drives with
// the arrow keys (parking) or traces with the mouse (writing) from the start screen through welcome,
// instructions, pre-test, diagnosis, drills (demo + practice), final test and summary, then finishes. The
// learner database must then hold the whole session, and the summary screenshot must match its golden. Shorter
// scripts drive one trial with a gamepad (unplugged and plugged in again mid-trial) and with the mouse
// joystick, and join a study in research mode. Bad script files must be refused with one error line naming
// the file and exit code 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/json_file.hpp"
#include "engine/render/rgba_image.hpp"
#include "engine/writing/writing_trial.hpp"
#include "teaching/records/learner_store.hpp"
#include "tests/support/golden_image.hpp"
#include "tests/support/run_skillcoach.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

namespace fs = std::filesystem;
using records::TrialKind;

fs::path fresh_dir(const std::string& name) { return test::fresh_scratch_dir("gui_script_" + name); }

fs::path script_file(const std::string& name) {
  const char* data = std::getenv("SKILLCOACH_TEST_DATA");
  return fs::path(data ? data : "tests") / "gui" / "data" / name;
}

// Runs the window with `script` in `dir` (screenshots land there), always offscreen: a developer's DISPLAY
// must not matter.
test::CommandResult run_script(const fs::path& script, const fs::path& dir) {
  return test::run_skillcoach("--data-dir '" + dir.string() + "' --script '" + script.string() + "'",
                              "cd '" + dir.string() + "' && SDL_VIDEODRIVER=offscreen");
}

// The screens the run showed, in order, from its "script: frame N screen NAME" lines.
std::vector<std::string> screens_shown(const std::string& output) {
  std::vector<std::string> screens;
  const std::string marker = " screen ";
  for (std::size_t at = output.find("script: frame "); at != std::string::npos;
       at = output.find("script: frame ", at + 1)) {
    const std::size_t line_end = output.find('\n', at);
    const std::string line = output.substr(at, line_end - at);
    if (const std::size_t m = line.find(marker); m != std::string::npos)
      screens.push_back(line.substr(m + marker.size()));
  }
  return screens;
}

long count_kind(const std::vector<records::StoredTrial>& trials, TrialKind kind) {
  return std::count_if(trials.begin(), trials.end(), [kind](const auto& t) { return t.record.kind == kind; });
}

// The learner's own input reached the simulation: some control step accelerates (the Up key) in a parking
// trial, and some points are inked with the pen down in a writing trial.
bool shows_learner_input(const std::string& task, const std::string& trajectory_json) {
  const Json doc = parse_json_text(trajectory_json, "trial");
  if (task == "parking") {
    const Json& actions = doc.at("actions");
    return std::any_of(actions.begin(), actions.end(), [](const Json& a) { return a.at(0).get<double>() > 0.5; });
  }
  const Json& points = doc.at("points");
  return points.size() > 10 && std::any_of(points.begin(), points.end(),
                                           [](const Json& p) { return p.size() < 3 || p.at(2).get<double>() > 0; });
}

void expect_whole_session(const fs::path& dir, const std::string& learner, const std::string& task,
                          const std::string& device) {
  records::LearnerStore store(dir);
  const auto learners = store.list_learners();
  ASSERT_EQ(learners.size(), 1u);
  EXPECT_EQ(learners[0].name, learner);  // typed on the welcome screen
  ASSERT_EQ(learners[0].sessions.size(), 1u);
  const auto& summary = learners[0].sessions[0];
  EXPECT_EQ(summary.session.task, task);
  EXPECT_TRUE(summary.session.finished.has_value()) << "the script presses Finish on the summary";
  const auto trials = store.trials_of_session(summary.session.id);
  EXPECT_EQ(count_kind(trials, TrialKind::Pretest), 5);
  EXPECT_EQ(count_kind(trials, TrialKind::Eval), 5);
  EXPECT_GE(count_kind(trials, TrialKind::Practice), 1);
  // A demo before each drill's first practice; "one more on this skill" plays it again without one.
  EXPECT_GE(count_kind(trials, TrialKind::Demo), 1);
  EXPECT_LE(count_kind(trials, TrialKind::Demo), count_kind(trials, TrialKind::Practice));
  for (const auto& t : trials) {
    EXPECT_EQ(t.record.task, task);
    ASSERT_FALSE(t.record.trajectory_json.empty()) << "trial " << t.seq;
    if (t.record.kind == TrialKind::Demo) continue;
    EXPECT_EQ(t.record.device, device) << "trial " << t.seq;
    ASSERT_TRUE(t.record.score.has_value()) << "trial " << t.seq;
    EXPECT_LE(*t.record.score, 0.0);
    EXPECT_TRUE(shows_learner_input(task, t.record.trajectory_json))
        << "trial " << t.seq << ": " << t.record.trajectory_json;
  }
  EXPECT_EQ(store.diagnoses_of_session(summary.session.id).size(), 1u);
  EXPECT_TRUE(summary.pretest_mean.has_value());
  EXPECT_TRUE(summary.eval_mean.has_value());
}

void expect_whole_flow(const test::CommandResult& run) {
  const std::vector<std::string> expected{"start",           "learn_welcome", "learn_instructions", "learn_trial",
                                          "learn_diagnosis", "learn_trial",   "learn_summary",      "start"};
  EXPECT_EQ(screens_shown(run.output), expected) << run.output;
  EXPECT_NE(run.output.find("finished at frame"), std::string::npos) << run.output;
}

// The run is frame-exact and the session seed fixed, so the summary it reached (scores, pictures, skills)
// is the same every time: a golden.
void expect_summary_screenshot(const fs::path& png, const std::string& golden) {
  ASSERT_TRUE(fs::exists(png)) << png;
  EXPECT_TRUE(test::matches_golden(read_png(png), golden));
}

// A whole session of `task` played by tests/gui/data/<task>_session.json: every screen in order, the summary
// golden, and the database.
fs::path expect_scripted_session(const std::string& task, const std::string& learner, const std::string& device) {
  const fs::path dir = fresh_dir(task);
  const test::CommandResult run = run_script(script_file(task + "_session.json"), dir);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  if (run.exit_code != 0) return dir;
  expect_whole_flow(run);
  expect_summary_screenshot(dir / (task + "_summary.png"), "gui/" + task + "_session_summary");
  expect_whole_session(dir, learner, task, device);
  return dir;
}

// The parking learner also asks for one more on the first drill's skill: the same drill, no second demo.
TEST(ScriptedGui, ParkingSessionThroughEveryScreen) {
  const fs::path dir = expect_scripted_session("parking", "Grace", "keyboard");
  records::LearnerStore store(dir);
  const auto trials = store.trials_of_session(store.list_learners().at(0).sessions.at(0).session.id);
  std::vector<int> practised;
  for (const auto& t : trials)
    if (t.record.kind == TrialKind::Practice) practised.push_back(t.record.drill_index.value_or(-1));
  EXPECT_EQ(practised, (std::vector<int>{0, 0}));
  EXPECT_EQ(count_kind(trials, TrialKind::Demo), 1);
}

TEST(ScriptedGui, WritingSessionThroughEveryScreen) { expect_scripted_session("writing", "Ketut", "mouse"); }

// The first pre-test trial of a run that then closes the window: kept with `device` and the learner's
// throttle in it, the session left unfinished.
void expect_one_kept_pretest_trial(const fs::path& dir, const std::string& device) {
  records::LearnerStore store(dir);
  const auto learners = store.list_learners();
  ASSERT_EQ(learners.size(), 1u);
  ASSERT_EQ(learners[0].sessions.size(), 1u);
  EXPECT_FALSE(learners[0].sessions[0].session.finished.has_value()) << "closed mid-session";
  const auto trials = store.trials_of_session(learners[0].sessions[0].session.id);
  ASSERT_EQ(trials.size(), 1u);
  EXPECT_EQ(trials[0].record.kind, TrialKind::Pretest);
  EXPECT_EQ(trials[0].record.device, device);
  EXPECT_TRUE(trials[0].record.score.has_value());
  EXPECT_TRUE(shows_learner_input("parking", trials[0].record.trajectory_json)) << trials[0].record.trajectory_json;
}

// The gamepad's stick drives; unplugged mid-trial the trial pauses and says why (screenshot), plugged in
// again it goes on and is kept.
TEST(ScriptedGui, GamepadDrivesATrialThatPausesWhileThePadIsUnplugged) {
  const fs::path dir = fresh_dir("gamepad");
  const test::CommandResult run = run_script(script_file("gamepad_trial.json"), dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(test::matches_golden(read_png(dir / "gamepad_unplugged.png"), "gui/gamepad_unplugged_pause"));
  expect_one_kept_pretest_trial(dir, "gamepad");
}

TEST(ScriptedGui, MouseDraggedOnScreenStickDrivesATrial) {
  const fs::path dir = fresh_dir("mouse_joystick");
  const test::CommandResult run = run_script(script_file("mouse_joystick_trial.json"), dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  expect_one_kept_pretest_trial(dir, "mouse-joystick");
}

// Esc mid-stroke stops the writing trial's clock for longer than its time limit: the pause card shows, ink
// moved while paused is dropped, and the kept trace's times leave the paused 40 s out.
TEST(ScriptedGui, EscPausesAWritingTrialWithoutTimingThePause) {
  const fs::path dir = fresh_dir("writing_pause");
  const test::CommandResult run = run_script(script_file("writing_pause_trial.json"), dir);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(test::matches_golden(read_png(dir / "writing_paused.png"), "gui/writing_paused"));
  records::LearnerStore store(dir);
  const auto learners = store.list_learners();
  ASSERT_EQ(learners.size(), 1u);
  const auto trials = store.trials_of_session(learners[0].sessions.at(0).session.id);
  ASSERT_EQ(trials.size(), 1u);
  EXPECT_EQ(trials[0].record.kind, TrialKind::Pretest);
  const writing::WritingTrial trial =
      writing::parse_writing_trial(parse_json_text(trials[0].record.trajectory_json, "trial"), "trial");
  ASSERT_FALSE(trial.times.empty());
  EXPECT_LT(trial.times.back(), 8.0) << "7 frames of 0.4 s of writing; the 40 s pause must not count";
  EXPECT_GT(trial.times.back(), 1.0);
  const auto far_right =
      std::find_if(trial.points.begin(), trial.points.end(), [](const auto& p) { return p.x > 250; });
  EXPECT_EQ(far_right, trial.points.end()) << "the mouse moved to the right while paused: no ink there";
}

// A class server that does not answer (a socket directory that does not exist): the welcome page says so
// and offers this computer's store; the learner's session then starts there, nothing is sent anywhere.
TEST(ScriptedGui, AnUnreachableClassServerOffersTrainingOnThisComputer) {
  const fs::path dir = fresh_dir("offline_start");
  const std::string store = "postgresql:///skillcoach?host=" + (dir / "no_server").string();
  const test::CommandResult run =
      test::run_skillcoach("--data-dir '" + dir.string() + "' --store '" + store + "' --script '" +
                               script_file("offline_start.json").string() + "'",
                           "cd '" + dir.string() + "' && SDL_VIDEODRIVER=offscreen");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::vector<std::string> expected{"start", "learn_welcome", "learn_instructions"};
  EXPECT_EQ(screens_shown(run.output), expected) << run.output;
  EXPECT_TRUE(fs::exists(dir / "offline_choice.png"));
  records::LearnerStore local(dir);
  const auto learners = local.list_learners();
  ASSERT_EQ(learners.size(), 1u);
  EXPECT_EQ(learners[0].name, "Ada");
  ASSERT_EQ(learners[0].sessions.size(), 1u);
  EXPECT_EQ(learners[0].sessions[0].session.task, "writing");
}

TEST(ScriptedGui, BadScriptIsOneErrorLineNamingTheFileAndExit2) {
  const fs::path dir = fresh_dir("bad");
  for (const char* name : {"bad_unknown_action.json", "bad_key_name.json", "bad_not_json.json"}) {
    const fs::path script = script_file(name);
    const test::CommandResult run = run_script(script, dir);
    EXPECT_EQ(run.exit_code, 2) << name << ": " << run.output;
    EXPECT_EQ(run.output.rfind("skillcoach: error: ", 0), 0u) << run.output;
    EXPECT_NE(run.output.find(script.string()), std::string::npos) << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  }
  const test::CommandResult missing = run_script(dir / "no_such_script.json", dir);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("no_such_script.json"), std::string::npos) << missing.output;
}

// Nested repeats: too deep crashed the reader (stack and memory), and 1000 x 1000 x 1000 empty passes
// ran for ever without adding a step. Both must be one error line, within a time limit.
TEST(ScriptedGui, DeepOrHugeRepeatsAreRefusedQuickly) {
  const fs::path dir = fresh_dir("repeats");
  std::string deep = R"({"steps":[)";
  for (int i = 0; i < 30000; ++i) deep += R"({"repeat":1,"steps":[)";
  for (int i = 0; i < 30000; ++i) deep += "]}";
  deep += "]}";
  const std::string wide =
      R"({"steps":[{"repeat":1000,"steps":[{"repeat":1000,"steps":[{"repeat":1000,"steps":[]}]}]}]})";
  const std::pair<std::string, std::string> cases[] = {{"deep.json", deep}, {"wide.json", wide}};
  for (const auto& [name, text] : cases) {
    test::write_bytes(dir / name, text);
    const auto run = test::run_skillcoach("--data-dir '" + dir.string() + "' --script '" + (dir / name).string() + "'",
                                          "timeout 60 env SDL_VIDEODRIVER=offscreen");
    EXPECT_EQ(run.exit_code, 2) << name << ": " << run.output.substr(0, 300);
    EXPECT_EQ(run.output.rfind("skillcoach: error: " + (dir / name).string() + ": $.steps[0]", 0), 0u)
        << run.output.substr(0, 300);
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output.substr(0, 300);
  }
}

TEST(ScriptedGui, AScreenThatNeverShowsFailsTheRunWithExit1) {
  const fs::path dir = fresh_dir("timeout");
  const test::CommandResult run = run_script(script_file("wrong_screen.json"), dir);
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("waiting for screen learn_summary (showing start)"), std::string::npos) << run.output;
}

// Research mode on the welcome page joins a study: the learner is enrolled, the session starts in the
// condition the study assigned (and belongs to the study), and the page never names the conditions.
TEST(ScriptedInput, ResearchModeJoinsAStudy) {
  const fs::path dir = fresh_dir("research_study");
  {
    records::LearnerStore store(dir);
    store.create_study({"pilot", "parking", {"skills", "full-trajectory"}, 5, 3, "2024-05-01T09:00:00.000Z"});
    store.enrol("pilot", "A1", "2024-05-01T09:30:00.000Z");
  }
  const auto result = run_script(script_file("research_study.json"), dir);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const records::LearnerStore store(dir, records::StoreOptions{.read_only = true});
  const auto participants = store.study_participants("pilot");
  ASSERT_EQ(participants.size(), 2u);
  EXPECT_EQ(participants[1].learner, "P13");
  const auto sessions = store.study_sessions("pilot");
  ASSERT_EQ(sessions.size(), 1u);
  EXPECT_EQ(sessions[0].session.learner, "P13");
  EXPECT_EQ(sessions[0].session.condition, participants[1].condition);
  // The page with the study chosen: its enrolment, "not shown", and no list of conditions.
  EXPECT_TRUE(test::matches_golden(read_png(dir / "research_study.png"), "gui/research_study"));
}

}  // namespace
}  // namespace sc
