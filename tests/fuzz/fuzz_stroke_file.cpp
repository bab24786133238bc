// Omniglot stroke files: the reader, then both preprocessing pipelines that turn a drawing into glyph
// steps (what the writing task does with every file it loads). Every glyph step must be finite.
#include <cmath>

#include "engine/core/error.hpp"
#include "engine/writing/glyph.hpp"
#include "engine/writing/stroke_file.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

void require_finite(const sc::writing::Glyph& glyph) {
  for (const auto& step : glyph.steps)
    sc::fuzz::fuzz_require(std::isfinite(step.dx) && std::isfinite(step.dy), "glyph step is not finite");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sc::writing::StrokeDrawing drawing;
  try {
    drawing = sc::writing::parse_stroke_text(sc::fuzz::as_text(data, size), "fuzz.txt");
  } catch (const sc::InputError&) {
    return 0;
  }
  sc::fuzz::fuzz_require(!drawing.strokes.empty(), "a parsed drawing has no strokes");
  for (const auto& stroke : drawing.strokes) sc::fuzz::fuzz_require(!stroke.empty(), "a parsed stroke is empty");
  try {
    require_finite(sc::writing::classic_glyph('a', drawing, "fuzz.txt"));
  } catch (const sc::InputError&) {}
  try {
    require_finite(sc::writing::balinese_glyph('B', drawing, "fuzz.txt"));
  } catch (const sc::InputError&) {}
  return 0;
}
