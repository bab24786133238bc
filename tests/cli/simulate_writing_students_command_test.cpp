// `skillcoach simulate-students --task writing --quick` end to end: prints the table and writes the JSON and
// the chart; bad input is one error line and exit code 2.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "engine/core/asset_paths.hpp"
#include "engine/core/json_file.hpp"
#include "tests/support/run_skillcoach.hpp"
#include "tests/support/scratch_files.hpp"

namespace sc {
namespace {

TEST(SimulateWritingStudentsCommand, QuickRunPrintsTheTableAndWritesJsonAndChart) {
  ASSERT_TRUE(std::filesystem::exists(test::skillcoach_binary())) << test::skillcoach_binary() << " is not built";
  const std::filesystem::path dir = test::scratch_path("simulate-students", "writing-quick");
  std::filesystem::remove_all(dir);
  const auto r =
      test::run_skillcoach("simulate-students --task writing --quick --seed 2 --out-dir '" + dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* text : {"Synthetic writing students", "missing 'a'", "half-trained", "Ind. Drills",
                           "Full Trajectory", "Wilcoxon signed-rank", "p = "})
    EXPECT_NE(r.output.find(text), std::string::npos) << text << "\n" << r.output;
  const Json doc = read_json_file(dir / "writing_students.json");
  EXPECT_EQ(doc.at("task"), "writing");
  EXPECT_EQ(doc.at("seed"), 2);
  ASSERT_EQ(doc.at("students").size(), 2u);
  for (const Json& s : doc.at("students")) {
    ASSERT_EQ(s.at("conditions").size(), 3u);
    const Json& pairs = s.at("conditions").at("Ind. Drills").at("pairs");
    for (const auto& [name, c] : s.at("conditions").items()) EXPECT_EQ(c.at("pairs"), pairs) << name;
  }
  const std::string png = test::read_bytes(dir / "writing_students.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(SimulateWritingStudentsCommand, BadInputIsOneLineAndExitCodeTwo) {
  const std::string parking_model = (asset_dir() / "models" / "parking.pt").string();
  for (const std::string& args : {std::string("--task writing --quick --model '") + parking_model + "'",  // mismatched
                                  std::string("--task writing --quick --model /nonexistent/writing.pt"),
                                  std::string("--task writing --words-per-set 0"),
                                  std::string("--task writing --seed -1"), std::string("--task drawing")}) {
    const auto r = test::run_skillcoach("simulate-students " + args + " --out-dir /tmp/none");
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("skillcoach: error: "), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
  }
}

}  // namespace
}  // namespace sc
