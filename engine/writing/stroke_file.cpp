#include "engine/writing/stroke_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/input_file.hpp"

namespace sc::writing {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Parses one finite decimal number; the whole field must be consumed.
bool parse_number(std::string_view field, double& out) {
  field = trim(field);
  if (field.empty()) return false;
  const char* end = field.data() + field.size();
  auto [ptr, ec] = std::from_chars(field.data(), end, out);
  return ec == std::errc{} && ptr == end && std::isfinite(out);
}

StrokeSample parse_sample(std::string_view line, const std::string& where) {
  double values[3];
  std::size_t start = 0;
  for (int k = 0; k < 3; ++k) {
    std::size_t comma = line.find(',', start);
    bool last = k == 2;
    if (last != (comma == std::string_view::npos))
      throw InputError(where, "expected \"x,y,t\" (three comma-separated numbers), got \"" + std::string(line) + "\"");
    std::string_view field = line.substr(start, last ? std::string_view::npos : comma - start);
    if (!parse_number(field, values[k]))
      throw InputError(where, "bad number \"" + std::string(trim(field)) + "\" (expected a finite decimal)");
    start = comma + 1;
  }
  return {values[0], values[1], values[2]};
}

}  // namespace

StrokeDrawing parse_stroke_text(std::string_view text, std::string_view source) {
  StrokeDrawing drawing;
  Stroke current;
  bool started = false;
  int line_number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    std::string_view line = trim(text.substr(pos, eol == std::string_view::npos ? std::string_view::npos : eol - pos));
    pos = eol == std::string_view::npos ? text.size() : eol + 1;
    ++line_number;
    const std::string where = std::string(source) + ": line " + std::to_string(line_number);
    if (line.empty()) continue;
    if (line == "START") {
      if (started) throw InputError(where, "second START (one character per file)");
      started = true;
    } else if (!started) {
      throw InputError(where, "data before START");
    } else if (line == "BREAK") {
      if (current.empty()) throw InputError(where, "empty stroke (BREAK without any x,y,t line)");
      drawing.strokes.push_back(std::move(current));
      current.clear();
    } else {
      current.push_back(parse_sample(line, where));
    }
  }
  const std::string at_end = std::string(source) + ": line " + std::to_string(line_number);
  if (!started) throw InputError(std::string(source), "no START line (not an Omniglot stroke file?)");
  if (!current.empty()) throw InputError(at_end, "truncated: the last stroke has no closing BREAK");
  if (drawing.strokes.empty()) throw InputError(at_end, "no strokes");
  return drawing;
}

StrokeDrawing read_stroke_file(const std::filesystem::path& file) {
  // Omniglot stroke files are a few kB; the JSON limit is ample.
  return parse_stroke_text(read_input_file(file, kMaxJsonFileBytes), file.string());
}

}  // namespace sc::writing
