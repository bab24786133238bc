// `skillcoach simulate-students --quick` end to end: prints the table and writes the JSON and the chart.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/json_file.hpp"
#include "tests/support/run_skillcoach.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

// Width and height from a PNG's IHDR chunk (big-endian at bytes 16..23).
std::pair<int, int> png_size(const std::string& bytes) {
  auto be32 = [&](std::size_t at) {
    int v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

TEST(SimulateStudentsCommand, QuickRunPrintsTheTableAndWritesJsonAndChart) {
  ASSERT_TRUE(std::filesystem::exists(test::skillcoach_binary())) << test::skillcoach_binary() << " is not built";
  const std::filesystem::path dir = test::scratch_path("simulate-students", "quick");
  std::filesystem::remove_all(dir);
  const auto r = test::run_skillcoach("simulate-students --quick --seed 3 --out-dir '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* text : {"half-trained", "reversing difficulty", "Ind. Drills", "Drills", "Full Trajectory",
                           "Wilcoxon signed-rank", "p = "})
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;

  const Json doc = read_json_file(dir / "students.json");
  EXPECT_EQ(doc.at("seed"), 3);
  ASSERT_EQ(doc.at("students").size(), 2u);
  for (const Json& s : doc.at("students")) {
    ASSERT_EQ(s.at("conditions").size(), 3u);
    const Json& pairs = s.at("conditions")[0].at("pairs");
    for (const Json& c : s.at("conditions")) EXPECT_EQ(c.at("pairs"), pairs);  // equal-size data per set
    EXPECT_EQ(s.at("conditions")[0].at("reward").at("per_set").size(), 4u);    // --quick: 4 sets
  }
  EXPECT_EQ(doc.at("wilcoxon").size(), 6u);

  const std::string png = test::read_bytes(dir / "students.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_EQ(png_size(png), (std::pair<int, int>{1280, 720}));

  // The students' own drives, the yardstick and the appendix curve.
  EXPECT_GT(doc.at("student_drives").at("pairs").get<int>(), 0);
  EXPECT_EQ(doc.at("reference").at("key"), "fully-trained");
  EXPECT_GT(doc.at("reference").at("heldout").at("mse").get<double>(), 0.0);
  EXPECT_EQ(doc.at("learning_curve").at("points").size(), 3u);  // --quick: epochs 0, 5, 20
  const std::string curve = test::read_bytes(dir / "students_curve.png");
  ASSERT_GT(curve.size(), 24u);
  EXPECT_EQ(png_size(curve), (std::pair<int, int>{1280, 720}));
}

TEST(SimulateStudentsCommand, StudyCornerIsRecordedAndBadSettingsAreOneLineErrors) {
  const std::filesystem::path dir = test::scratch_path("simulate-students", "corner");
  std::filesystem::remove_all(dir);
  const auto r =
      test::run_skillcoach("simulate-students --quick --study-corner --no-curve --out-dir '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json doc = read_json_file(dir / "students.json");
  EXPECT_EQ(doc.at("config").at("region"), "study-corner");
  EXPECT_FALSE(doc.contains("learning_curve"));
  EXPECT_FALSE(std::filesystem::exists(dir / "students_curve.png"));
  for (const char* bad :
       {"--finetune-lr 0", "--finetune-epochs 0", "--student-drives -3", "--rehearsal 101", "--reverse-keep 1.5"}) {
    const auto e = test::run_skillcoach(std::string("simulate-students --quick ") + bad + " --out-dir /tmp/none");
    EXPECT_EQ(e.exit_code, 2) << bad << "\n" << e.output;
  }
}

TEST(SimulateStudentsCommand, RefusesAMissingModelFile) {
  const auto r = test::run_skillcoach("simulate-students --quick --model /nonexistent/parking.pt --out-dir /tmp/none");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("skillcoach: error: "), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sc
