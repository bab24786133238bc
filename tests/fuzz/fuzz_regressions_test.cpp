// Regression tests for what the fuzzers found (docs/hardening.md, "Findings"), asserting the specific
// outcome that the corpus replay alone (which only checks "no crash") cannot see.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "engine/core/error.hpp"
#include "engine/writing/glyph.hpp"
#include "engine/writing/stroke_file.hpp"

namespace {

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

}  // namespace
