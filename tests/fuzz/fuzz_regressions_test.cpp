// Regression tests for what the fuzzers found (docs/hardening.md, "Findings"), asserting the specific
// outcome that the corpus replay alone (which only checks "no crash") cannot see.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/json_file.hpp"
#include "engine/writing/glyph.hpp"
#include "engine/writing/stroke_file.hpp"
#include "teaching/records/records_export.hpp"
#include "tests/support/scratch_files.hpp"

namespace {

std::string read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::filesystem::path scratch(const char* name) {
  auto dir = std::filesystem::path(std::getenv("SKILLCOACH_TEST_OUTPUT")) / "fuzz_regressions" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path regression(const char* target, const char* name) {
  return std::filesystem::path(std::getenv("SKILLCOACH_TEST_DATA")) / "fuzz" / "regressions" / target / name;
}

// A real stroke file with one sample's y mangled to -322516: the classic pipeline scaled the stroke to
// 100 px wide and infilled ~1.4 million 1-px steps (12 s and 400 MB under ASan; a larger value exhausts
// memory). It must be refused with a message instead.
TEST(FuzzRegressions, ClassicGlyphRefusesAStrokeWithOneWildSample) {
  const auto drawing = sc::writing::read_stroke_file(regression("stroke_file", "classic_wild_sample_infill_hang.txt"));
  EXPECT_THROW(sc::writing::classic_glyph('a', drawing, "wild"), sc::InputError);
  EXPECT_NO_THROW(sc::writing::balinese_glyph('B', drawing, "wild"));  // fits a 100 px box: bounded
}

// A tiny positive width (2.5e-308) made the scale infinite and every point NaN or infinite.
TEST(FuzzRegressions, ClassicGlyphRefusesASubnormalWidth) {
  const auto drawing = sc::writing::parse_stroke_text("START\n0,0,0\n2.5e-308,0,10\nBREAK\n", "tiny.txt");
  EXPECT_THROW(sc::writing::classic_glyph('a', drawing, "tiny"), sc::InputError);
}

// A learner database whose text column holds a byte that is not UTF-8 (0xC5 alone): the export threw
// nlohmann's type_error 316 from dump(), an uncaught non-InputError that lost the whole export (and left
// "<out>.tmp" behind). write_json_file now writes such bytes as U+FFFD.
TEST(FuzzRegressions, ExportOfADatabaseWithInvalidUtf8TextSucceeds) {
  const auto dir = scratch("invalid_utf8");
  const std::string input = read_bytes(regression("learner_database", "invalid_utf8_in_text_column.db"));
  ASSERT_GT(input.size(), 1u);
  std::ofstream(dir / "skillcoach.db", std::ios::binary) << input.substr(1);  // byte 0 selects the mode
  const auto out = dir / "export.json";
  EXPECT_NO_THROW(sc::records::export_database(dir, out));
  EXPECT_NE(read_bytes(out).find("\xEF\xBF\xBD"), std::string::npos);
  EXPECT_EQ(sc::test::temporaries_left_of(out), 0);
}

TEST(FuzzRegressions, JsonFilesReplaceInvalidUtf8InsteadOfThrowing) {
  const auto file = scratch("utf8") / "doc.json";
  sc::write_json_file(file, sc::Json{{"device", std::string("pad\xC5")}});
  EXPECT_EQ(sc::read_json_file(file).at("device").get<std::string>(), "pad\xEF\xBF\xBD");
}

}  // namespace
