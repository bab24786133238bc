#include "engine/writing/writing_trial.hpp"

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"

namespace sc::writing {
namespace {

std::filesystem::path test_data(const std::string& name) {
  const char* root = std::getenv("SKILLCOACH_TEST_DATA");
  return std::filesystem::path(root ? root : "tests") / "writing" / "data" / name;
}

std::filesystem::path scratch(const std::string& name) {
  const char* out = std::getenv("SKILLCOACH_TEST_OUTPUT");
  std::filesystem::path dir = std::filesystem::path(out ? out : "/tmp") / "writing";
  std::filesystem::create_directories(dir);
  return dir / name;
}

std::string error_of(const std::string& text) {
  try {
    parse_writing_trial(parse_json_text(text, "t.json"), "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kScenario = R"("scenario": {"word": "ab", "alphabet": "classic"})";

TEST(WritingTrialFile, ReadsClassicTrialIgnoringUnknownFields) {
  const auto trial = read_writing_trial(test_data("trial_classic.json"));
  EXPECT_EQ(trial.scenario.word, "ab-c");
  EXPECT_EQ(trial.scenario.alphabet, AlphabetKind::Classic);
  ASSERT_EQ(trial.points.size(), 4u);
  EXPECT_EQ(trial.points[2], (TracePoint{0.5, 148.25, true}));
  EXPECT_EQ(trial.times[3], 0.05);
  EXPECT_EQ(trial.score, -0.98);
  EXPECT_EQ(trial.source, "learner");
  EXPECT_EQ(trial.device, "trackpad");
  EXPECT_TRUE(trial.warnings.empty());
}

TEST(WritingTrialFile, ReadsBalineseTrialWithDrawersAndPen) {
  const auto trial = read_writing_trial(test_data("trial_balinese.json"));
  EXPECT_EQ(trial.scenario.alphabet, AlphabetKind::Balinese);
  EXPECT_EQ(trial.scenario.drawers, (DrawerChoice{{'B', 7}, {'P', 15}}));
  EXPECT_FALSE(trial.points[1].pen);
  EXPECT_TRUE(trial.points[2].pen);
  EXPECT_TRUE(trial.times.empty());
  EXPECT_FALSE(trial.score.has_value());
}

TEST(WritingTrialFile, RoundTrip) {
  for (const char* name : {"trial_classic.json", "trial_balinese.json"}) {
    const auto trial = read_writing_trial(test_data(name));
    const auto file = scratch(std::string("roundtrip_") + name);
    write_writing_trial(file, trial);
    const auto again = read_writing_trial(file);
    EXPECT_EQ(again.scenario, trial.scenario);
    EXPECT_EQ(again.points, trial.points);
    EXPECT_EQ(again.times, trial.times);
    EXPECT_EQ(again.score, trial.score);
    EXPECT_EQ(again.device, trial.device);
  }
}

TEST(WritingTrialFile, GoldTrialIsTheExpertTrajectory) {
  const WritingScenario scenario{"ab-c", AlphabetKind::Classic, {}};
  const auto gold = gold_trial(scenario);
  const auto traj = gold_trajectory(scenario);
  EXPECT_EQ(gold.points, traj.points());
  EXPECT_EQ(gold.source, "expert");
  ASSERT_EQ(gold.times.size(), gold.points.size());
  EXPECT_DOUBLE_EQ(gold.times.back(), static_cast<double>(traj.steps.size()) / kExpertStepsPerSecond);
  // Classic gold is all ink: written as [x, y] pairs.
  EXPECT_EQ(writing_trial_json(gold)["points"][5].size(), 2u);
  const auto bali = gold_trial({"B-P", AlphabetKind::Balinese, {{'B', 7}}});
  EXPECT_EQ(writing_trial_json(bali)["points"][5].size(), 3u);
  EXPECT_EQ(writing_trial_json(bali)["scenario"]["drawers"]["B"], 7);
}

TEST(WritingTrialFile, MalformedFilesGiveOneLineWithPathAndProblem) {
  EXPECT_EQ(error_of("[1]"), "t.json: $: expected a JSON object (a writing trial)");
  EXPECT_EQ(error_of(R"({"task": "parking", )" + kScenario + R"(, "points": []})"),
            "t.json: $.task: expected \"writing\", got \"parking\"");
  EXPECT_EQ(error_of(R"({"task": "writing", "points": []})"), "t.json: $: missing required field \"scenario\"");
  EXPECT_EQ(error_of(R"({"task": "writing", "scenario": {"word": "az"}, "points": []})"),
            "t.json: $.scenario.word: 'z' is not a symbol of the classic alphabet (valid: abcte-^)");
  EXPECT_EQ(error_of(R"({"task": "writing", "scenario": {"word": "a", "alphabet": "latin"}, "points": []})"),
            "t.json: $.scenario.alphabet: unknown alphabet \"latin\" (expected \"classic\" or \"balinese\")");
  EXPECT_EQ(error_of(R"({"task": "writing", "scenario": {"word": "a", "drawers": {"a": 2}}, "points": []})"),
            "t.json: $.scenario.drawers: drawer choices need \"alphabet\": \"balinese\" (classic always uses the "
            "paper's drawers)");
  EXPECT_EQ(
      error_of(
          R"({"task": "writing", "scenario": {"word": "A", "alphabet": "balinese", "drawers": {"A": 0}}, "points": []})"),
      "t.json: $.scenario.drawers.A: drawer must be in 1..15");
  EXPECT_EQ(
      error_of(
          R"({"task": "writing", "scenario": {"word": "A", "alphabet": "balinese", "drawers": {"Z": 1}}, "points": []})"),
      "t.json: $.scenario.drawers.Z: \"Z\" is not a character of the balinese alphabet (A..X)");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[1, 2], [3]]})"),
            "t.json: $.points[1]: expected [x, y] or [x, y, pen], got 1 elements");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[1, "a"]]})"),
            "t.json: $.points[0][1]: expected a number, got string");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[1, 2, 2]]})"),
            "t.json: $.points[0][2]: pen must be 0 (lifted) or 1 (drawing)");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[1, 1e300]]})"),
            "t.json: $.points[0][1]: value 1e+300 is outside [-10000, 10000]");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": {"x": 1}})"),
            "t.json: $.points: expected an array, got object");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[1, 2]], "t": [0, 1]})"),
            "t.json: $.t: has 2 time stamps for 1 points");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[1, 2], [2, 2]], "t": [1, 0.5]})"),
            "t.json: $.t[1]: time goes backwards");
  EXPECT_EQ(error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[1, 2]], "score": 0.5})"),
            "t.json: $.score: value 0.5 is outside [-1, 0]");
  // NaN and Infinity are not JSON: the parser rejects them with the position.
  EXPECT_NE(
      error_of(R"({"task": "writing", )" + kScenario + R"(, "points": [[NaN, 2]]})").find("t.json: not valid JSON"),
      std::string::npos);
  EXPECT_THROW(read_writing_trial(test_data("missing.json")), InputError);
}

TEST(WritingTrialFile, AbsurdlyLongTracesAreCappedWithAWarning) {
  Json doc{{"task", "writing"}, {"scenario", {{"word", "a"}}}, {"points", Json::array()}, {"t", Json::array()}};
  for (std::size_t i = 0; i < kMaxTrialPoints + 5; ++i) {
    doc["points"].push_back({1.0, 2.0});
    doc["t"].push_back(static_cast<double>(i));
  }
  const auto trial = parse_writing_trial(doc, "long.json");
  EXPECT_EQ(trial.points.size(), kMaxTrialPoints);
  EXPECT_EQ(trial.times.size(), kMaxTrialPoints);
  ASSERT_EQ(trial.warnings.size(), 1u);
  EXPECT_EQ(trial.warnings[0], "long.json: $.points: 200005 points; kept the first 200000");
}

}  // namespace
}  // namespace sc::writing
