// `skillcoach segment` end to end: JSON output, the PNG, and refused models.
#include <gtest/gtest.h>

#include "tests/cli/skills_cli_fixture.hpp"

namespace sc {
namespace {

using test::run_skillcoach;
using test::scratch_path;

Json json_of(const std::string& output) {
  const auto start = output.find('{');
  EXPECT_NE(start, std::string::npos) << output;
  return Json::parse(output.substr(start == std::string::npos ? 0 : start));
}

TEST(SegmentCommand, PrintsSegmentsCoveringTheTrialWithSkillsAndInteriorBoundaries) {
  const auto model = test::tiny_model("writing");
  const auto trial = test::wavy_writing_trial("segment.json");
  const auto r = run_skillcoach("segment --task writing --model " + model.string() + " " + trial.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json d = json_of(r.output);
  EXPECT_EQ(d.at("extractor"), "compile");
  const Json& segments = d.at("segments");
  ASSERT_FALSE(segments.empty());
  EXPECT_LE(segments.size(), 8u);  // K = 8 for writing
  EXPECT_EQ(d.at("skills").size(), segments.size());
  EXPECT_EQ(d.at("boundaries").size(), segments.size() - 1);
  int expected_begin = 0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    EXPECT_EQ(segments[i].at("begin"), expected_begin);
    EXPECT_GT(segments[i].at("end").get<int>(), expected_begin);
    EXPECT_EQ(segments[i].at("skill"), d.at("skills")[i]);
    if (i + 1 < segments.size()) {
      EXPECT_EQ(d.at("boundaries")[i], segments[i].at("end"));
    }
    expected_begin = segments[i].at("end");
  }
  EXPECT_EQ(expected_begin, d.at("steps"));
}

TEST(SegmentCommand, DrawsTheSegmentsIntoAPng) {
  const auto model = test::tiny_model("writing");
  const auto trial = test::wavy_writing_trial("segment_png.json");
  const auto png = scratch_path("segment", "wavy.png");
  std::filesystem::remove(png);
  const auto r = run_skillcoach("segment --task writing --size 640x384 --png " + png.string() + " --model " +
                                model.string() + " " + trial.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string bytes = test::read_bytes(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}

TEST(SegmentCommand, TruncatedModelIsOneErrorLineAndExitTwo) {
  const std::string good = test::read_bytes(test::tiny_model("writing"));
  const auto cut = scratch_path("segment", "truncated.pt");
  test::write_bytes(cut, good.substr(0, good.size() / 2));
  const auto r = run_skillcoach("segment --task writing --model " + cut.string() + " " +
                                test::wavy_writing_trial("segment_cut.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(test::count_lines(r.output), 1) << r.output;
  EXPECT_EQ(r.output.rfind("skillcoach: error: " + cut.string(), 0), 0u) << r.output;
}

TEST(SegmentCommand, ModelOfAnotherTaskOrMissingModelIsRefused) {
  const auto parking_model = test::tiny_model("parking");
  const auto trial = test::wavy_writing_trial("segment_task.json");
  const auto wrong = run_skillcoach("segment --task writing --model " + parking_model.string() + " " + trial.string());
  EXPECT_EQ(wrong.exit_code, 2) << wrong.output;
  EXPECT_NE(wrong.output.find("trained for task \"parking\""), std::string::npos) << wrong.output;
  EXPECT_EQ(test::count_lines(wrong.output), 1) << wrong.output;
  const auto missing = run_skillcoach("segment --task writing --model /nonexistent/model.pt " + trial.string());
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_EQ(test::count_lines(missing.output), 1) << missing.output;
}

TEST(SegmentCommand, TrialOfAnotherTaskIsRefused) {
  const auto r = run_skillcoach("segment --task parking --model " + test::tiny_model("parking").string() + " " +
                                test::wavy_writing_trial("segment_other.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not a parking trial"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sc
