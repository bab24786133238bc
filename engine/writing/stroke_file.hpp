#pragma once
// Reader for Omniglot's raw stroke files: a line "START", then one "x,y,t" line per pen sample (motor
// coordinates, y up, t in ms), and a line "BREAK" after every stroke (pen up). Corrupt files throw
// sc::InputError naming the file and the line ("0109_04.txt: line 12: bad number \"1.2.3\"").
#include <filesystem>
#include <string_view>
#include <vector>

namespace sc::writing {

struct StrokeSample {
  double x = 0.0;  // motor coordinates: y points UP
  double y = 0.0;
  double t = 0.0;  // milliseconds
};

using Stroke = std::vector<StrokeSample>;

// One drawing of one character by one drawer: its strokes in drawing order (never empty, no empty stroke).
struct StrokeDrawing {
  std::vector<Stroke> strokes;
};

StrokeDrawing read_stroke_file(const std::filesystem::path& file);
// `source` names the text in error messages (usually the file name).
StrokeDrawing parse_stroke_text(std::string_view text, std::string_view source);

}  // namespace sc::writing
