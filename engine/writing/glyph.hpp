#pragma once
// Glyphs: the expert's relative pen moves for one symbol (a character or a connector), and the
// preprocessing that turns an Omniglot drawing into them.
//  * classic  = the paper's pipeline, reference-facts §2.4, bit for bit (first stroke only, no pen lifts).
//  * balinese = our extension for the full alphabet: every stroke, pen-up moves between strokes.
#include <string>
#include <string_view>
#include <vector>

#include "engine/writing/stroke_file.hpp"
#include "engine/writing/trace_point.hpp"

namespace sc::writing {

inline constexpr double kScaleWidth = 100.0;             // DRAWING_SCALE_WIDTH: characters are 100 px wide
inline constexpr std::size_t kMinCharacterPoints = 380;  // DRAWING_TRAJ_LEN: padding target (§2.4 step 5)

// One action: a relative pen move in canvas pixels; pen = true draws ink, false moves the lifted pen.
struct WritingStep {
  double dx = 0.0;
  double dy = 0.0;
  bool pen = true;
  bool operator==(const WritingStep&) const = default;
};

struct Glyph {
  char symbol = '?';
  std::string source;              // e.g. "character02/0109_04.txt", or "connector"
  std::vector<WritingStep> steps;  // starts at the pen position where the previous symbol ended
};

// Classic preprocessing up to step 5 (absolute image coordinates, before taking differences).
struct ClassicCharacterPoints {
  std::vector<Point2> points;
  int lead_in_points = 0;  // points prepended by the baseline lead-in rule (step 4)
};
// `source` names the drawing in errors (a zero-width first stroke).
ClassicCharacterPoints classic_character_points(const StrokeDrawing& drawing, std::string_view source = "stroke file");
// Steps = consecutive differences of classic_character_points (step 6), all pen-down.
Glyph classic_glyph(char symbol, const StrokeDrawing& drawing, std::string source);

// Full-alphabet glyph (our extension, see docs/trajectory-format.md "Writing trials"): all strokes; y negated;
// scaled so the drawing fits a 100 x 100 px box (tall characters would not fit the 300 px canvas at 100 px
// width); placed with its left edge at the entry point and its bottom on the entry point's line (the word's
// baseline); each stroke infilled with the reference rule; the pen moves lifted, in <= 1 px steps, from the
// entry point to the first stroke, between strokes, and from the last stroke to the exit point
// (width, 0) on the baseline, so characters chain like the classic ones. A one-point stroke (a dot) is a
// single zero-length pen-down step.
Glyph balinese_glyph(char symbol, const StrokeDrawing& drawing, std::string source);

// The connectors: '-' = 20 steps (+1, 0); '^' = 20 steps (+1, -2) then 20 steps (+1, +2) (§2.4 table).
Glyph connector_glyph(char symbol);

}  // namespace sc::writing
