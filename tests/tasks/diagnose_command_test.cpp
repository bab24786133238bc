// End-to-end checks of `skillcoach diagnose` through SKILLCOACH_BINARY.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/json_file.hpp"

namespace sc {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const char* dir = std::getenv("SKILLCOACH_TEST_OUTPUT");
  std::filesystem::path p = std::filesystem::path(dir ? dir : ".") / "diagnose" / name;
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p.parent_path());
  return p;
}

struct Result {
  int status = -1;
  std::string output;
};

// `environment`: "NAME=value" assignments for the command, or empty.
Result run(const std::string& arguments, const std::string& name, const std::string& environment = "") {
  const auto log = scratch(name + ".log");
  const std::string command = environment + (environment.empty() ? "" : " ") + std::getenv("SKILLCOACH_BINARY") + " " +
                              arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

TEST(DiagnoseCommand, WritingLearnerGetsSkillsExpertiseTargetsAndDrawnDrills) {
  const auto trial = scratch("line.json");
  Json doc = {{"task", "writing"}, {"scenario", {{"word", "b-a-t---"}}}, {"points", Json::array()}};
  for (int x = 0; x < 400; x += 2) doc["points"].push_back({x, 150});
  write_json_file(trial, doc);
  const auto out = scratch("writing.json");
  const auto png = scratch("writing_png");
  const Result r =
      run("diagnose --task writing --png " + png.string() + " --out " + out.string() + " " + trial.string(), "writing");
  ASSERT_EQ(r.status, 0) << r.output;
  const Json d = read_json_file(out);
  EXPECT_EQ(d.at("task"), "writing");
  EXPECT_EQ(d.at("expertise_mode"), "quality-aware");  // the trainer's default for writing
  ASSERT_TRUE(d.at("noise_floor").is_number());        // writing's calibrated floor, inside the score's range
  EXPECT_LT(d.at("noise_floor").get<double>(), 0.0);
  EXPECT_GT(d.at("noise_floor").get<double>(), -1.0);
  ASSERT_EQ(d.at("trials").size(), 1u);
  EXPECT_EQ(d.at("trials")[0].at("file"), trial.string());
  EXPECT_LT(d.at("trials")[0].at("reward").get<double>(), -0.5);  // a straight line is far from the word
  EXPECT_FALSE(d.at("trials")[0].at("skills").empty());
  EXPECT_LE(d.at("targets").size(), 8u);  // N_target = 8 for writing
  ASSERT_FALSE(d.at("drills").empty());
  for (std::size_t i = 0; i < d.at("drills").size(); ++i) {
    const Json& drill = d.at("drills")[i];
    EXPECT_EQ(drill.at("repetitions"), 3);  // N_rep = 3 for writing
    EXPECT_EQ(drill.at("ghost_path").size(), drill.at("trial").at("points").size());
    EXPECT_TRUE(std::filesystem::exists(png / ("drill_" + std::to_string(i + 1) + ".png")));
  }
}

// A shipped writing model whose sidecar records a floor that is not a number (a damaged install): the learner
// is still diagnosed, without a floor, and the note says which file and why; it is not refused as a user's
// own model would be.
TEST(DiagnoseCommand, ADamagedShippedSidecarFallsBackToNoNoiseFloorWithANote) {
  const std::filesystem::path assets = std::getenv("SKILLCOACH_ASSET_DIR");
  const auto copy = scratch("damaged_assets");
  std::filesystem::create_directories(copy / "models");
  for (const auto& entry : std::filesystem::directory_iterator(assets))
    if (entry.path().filename() != "models")
      std::filesystem::create_directory_symlink(entry.path(), copy / entry.path().filename());
  for (const char* file : {"writing.pt", "parking.pt", "parking.pt.json"})
    std::filesystem::create_symlink(assets / "models" / file, copy / "models" / file);
  Json sidecar = read_json_file(assets / "models" / "writing.pt.json");
  sidecar["execution_noise_floor"]["value"] = "low";
  write_json_file(copy / "models" / "writing.pt.json", sidecar);

  const auto trial = scratch("damaged_line.json");
  Json doc = {{"task", "writing"}, {"scenario", {{"word", "b-a-t---"}}}, {"points", Json::array()}};
  for (int x = 0; x < 400; x += 2) doc["points"].push_back({x, 150});
  write_json_file(trial, doc);
  const auto out = scratch("damaged.json");
  const Result r = run("diagnose --task writing --out " + out.string() + " " + trial.string(), "damaged",
                       "SKILLCOACH_ASSET_DIR=" + copy.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find((copy / "models" / "writing.pt.json").string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("without a noise floor"), std::string::npos) << r.output;
  const Json d = read_json_file(out);
  EXPECT_EQ(d.at("expertise_mode"), "quality-aware");
  EXPECT_TRUE(d.at("noise_floor").is_null());
  EXPECT_FALSE(d.at("targets").empty());
}

TEST(DiagnoseCommand, ParkingLearnerOnAPoolScenarioIsComparedWithThatExpert) {
  const Json pool =
      read_json_file(std::filesystem::path(std::getenv("SKILLCOACH_ASSET_DIR")) / "experts" / "parking_pool.json");
  Json learner = pool.at("trials")[4];
  learner.erase("states");
  learner.erase("rewards");
  learner.erase("success");
  learner["source"] = "learner";
  Json& actions = learner.at("actions");
  actions.erase(actions.begin() + static_cast<long>(actions.size() / 2), actions.end());  // gives up half-way
  const auto trial = scratch("half.json");
  write_json_file(trial, learner);
  const auto out = scratch("parking.json");
  const Result r = run("diagnose --task parking --out " + out.string() + " " + trial.string(), "parking");
  ASSERT_EQ(r.status, 0) << r.output;
  const Json d = read_json_file(out);
  EXPECT_EQ(d.at("trials")[0].at("pool_index"), 4);
  EXPECT_LT(d.at("trials")[0].at("reward").get<double>(), pool.at("trials")[4].at("rewards").back().get<double>());
  for (const Json& drill : d.at("drills")) {
    EXPECT_EQ(drill.at("trial").at("task"), "parking");
    EXPECT_TRUE(drill.at("trial").at("scenario").contains("start"));
    EXPECT_EQ(drill.at("ghost_path").size(), drill.at("trial").at("states").size());
  }
}

TEST(DiagnoseCommand, QualityAwareExpertiseAddsToAlg2AndEveryTargetSaysWhyAndWhere) {
  const Json pool =
      read_json_file(std::filesystem::path(std::getenv("SKILLCOACH_ASSET_DIR")) / "experts" / "parking_pool.json");
  Json learner = pool.at("trials")[4];
  for (const char* key : {"states", "rewards", "success"}) learner.erase(key);
  Json& actions = learner.at("actions");
  actions.erase(actions.begin() + static_cast<long>(actions.size() / 2), actions.end());
  const auto trial = scratch("half_quality.json");
  write_json_file(trial, learner);
  const auto alg2 = scratch("alg2.json"), quality = scratch("quality.json");
  ASSERT_EQ(run("diagnose --task parking --out " + alg2.string() + " " + trial.string(), "alg2").status, 0);
  const Result r = run(
      "diagnose --task parking --expertise quality-aware --out " + quality.string() + " " + trial.string(), "quality");
  ASSERT_EQ(r.status, 0) << r.output;
  const Json a = read_json_file(alg2), q = read_json_file(quality);
  EXPECT_EQ(a.at("expertise_mode"), "alg2");
  EXPECT_EQ(q.at("expertise_mode"), "quality-aware");
  EXPECT_TRUE(a.at("noise_floor").is_null());
  EXPECT_TRUE(q.at("noise_floor").is_null());  // parking uses none
  const Json& ea = a.at("expertise").at("expertise");
  const Json& eq = q.at("expertise").at("expertise");
  for (std::size_t m = 0; m < ea.size(); ++m) EXPECT_LE(eq[m].get<double>(), ea[m].get<double>() + 1e-12) << m;
  const int learner_steps = static_cast<int>(actions.size());
  ASSERT_FALSE(q.at("targets").empty());
  for (const Json* doc : {&a, &q})
    for (const Json& t : doc->at("targets")) {
      const Json& why = t.at("why");
      const std::string reason = why.at("reason");
      EXPECT_TRUE(reason == "missing" || reason == "done with a large error here" || reason == "no mistake seen" ||
                  reason == "done a little wrong every time")
          << t;
      EXPECT_EQ(reason == "no mistake seen", why.at("penalty").get<double>() == 0.0) << t;
      EXPECT_EQ(why.at("trial"), 0);
      EXPECT_GE(why.at("learner_steps")[0].get<int>(), 0);
      EXPECT_LE(why.at("learner_steps")[1].get<int>(), learner_steps);
      EXPECT_LT(why.at("expert_steps")[0].get<int>(), why.at("expert_steps")[1].get<int>());
    }
}

TEST(DiagnoseCommand, TrialOfAnotherTaskIsAnInputErrorNamingTheFile) {
  const auto trial = scratch("wrong.json");
  write_json_file(trial, Json{{"task", "parking"}, {"scenario", {{"word", "ab"}}}, {"points", Json::array()}});
  const Result r = run("diagnose --task writing " + trial.string(), "wrong");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(trial.string() + ": $.task: expected \"writing\""), std::string::npos) << r.output;
}

// The second of three files is bad: the message names that file and the whole JSON path, also inside the
// scenario.
TEST(DiagnoseCommand, ABadFileAmongSeveralIsNamedWithItsFullJsonPath) {
  const char* data = std::getenv("SKILLCOACH_TEST_DATA");
  const auto good = std::filesystem::path(data ? data : "tests") / "parking" / "data" / "expert_trial.json";
  Json doc = read_json_file(good);
  ASSERT_GE(doc.at("actions").size(), 2u);
  doc["actions"][1][0] = 1.5;
  const auto bad_action = scratch("bad_action.json");
  write_json_file(bad_action, doc);
  const Result r =
      run("diagnose --task parking " + good.string() + " " + bad_action.string() + " " + good.string(), "bad_action");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(
      r.output.find("skillcoach: error: " + bad_action.string() + ": $.actions[1][0]: value 1.5 is outside [-1, 1]"),
      std::string::npos)
      << r.output;
  doc = read_json_file(good);
  doc["scenario"]["heading0"] = "north";
  const auto bad_scenario = scratch("bad_scenario.json");
  write_json_file(bad_scenario, doc);
  const Result s = run("diagnose --task parking " + good.string() + " " + bad_scenario.string(), "bad_scenario");
  EXPECT_EQ(s.status, 2) << s.output;
  EXPECT_NE(s.output.find(bad_scenario.string() + ": $.scenario.heading0: expected a number"), std::string::npos)
      << s.output;
}

}  // namespace
}  // namespace sc
