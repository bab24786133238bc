#include "engine/writing/glyph.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"
#include "engine/writing/infill.hpp"

namespace sc::writing {
namespace {

// Omniglot's space_motor_to_img: y up -> y down, nothing else.
std::vector<Point2> image_points(const Stroke& stroke) {
  std::vector<Point2> pts;
  pts.reserve(stroke.size());
  for (const auto& s : stroke) pts.push_back({s.x, -s.y});
  return pts;
}

void append_differences(const std::vector<Point2>& pts, bool pen, std::vector<WritingStep>& steps) {
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    steps.push_back({pts[i + 1].x - pts[i].x, pts[i + 1].y - pts[i].y, pen});
}

void append_pen_up_move(const Point2& from, const Point2& to, std::vector<WritingStep>& steps) {
  if (from == to) return;
  append_differences(infill_reference({from, to}), false, steps);
}

// Height/width limit of a classic first stroke (see classic_character_points).
constexpr double kMaxClassicAspect = 20.0;

}  // namespace

ClassicCharacterPoints classic_character_points(const StrokeDrawing& drawing, std::string_view source) {
  if (drawing.strokes.empty()) throw std::invalid_argument("classic_character_points: no strokes");
  // Step 1: first stroke only (all five paper characters have exactly one).
  std::vector<Point2> pts = image_points(drawing.strokes.front());
  // Step 2: scale both coordinates so the stroke is exactly 100 px wide (no translation).
  auto [min_x, max_x] = std::minmax_element(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.x < b.x; });
  const double width = max_x->x - min_x->x;
  if (!(width > 0.0) || !std::isfinite(kScaleWidth / width))  // a width of 1e-308 is zero for scaling
    throw InputError(source, "first stroke has zero width");
  const double scale = kScaleWidth / width;
  // The shipped first strokes are at most 3x as tall as wide. One wild sample in a damaged file (found by
  // tests/fuzz) made step 3 infill millions of points and hang the loader; refuse such a stroke instead.
  auto [min_y, max_y] = std::minmax_element(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.y < b.y; });
  const double aspect = (max_y->y - min_y->y) / width;
  if (!(aspect <= kMaxClassicAspect))
    throw InputError("classic character", "first stroke is more than 20 times as tall as wide (corrupt stroke file?)");
  for (auto& p : pts) p = {p.x * scale, p.y * scale};
  // Step 3: infill to <= 1 px steps.
  pts = infill_reference(pts);
  // Step 4: baseline lead-in. The reference runs `for k in range(int(y0), ceil(y_last))`, inserting
  // (x0, k) at the front each time, so the prefix reads ceil(y_last) - 1, ..., int(y0). int() truncates
  // toward zero (floor only for positive y), which we keep.
  ClassicCharacterPoints out;
  const Point2 first = pts.front();
  const double y_last = pts.back().y;
  std::vector<Point2> lead_in;
  if (y_last > first.y) {
    const long long top = static_cast<long long>(std::trunc(first.y));
    const long long bottom = static_cast<long long>(std::ceil(y_last));
    for (long long k = bottom - 1; k >= top; --k) lead_in.push_back({first.x, static_cast<double>(k)});
  }
  out.lead_in_points = static_cast<int>(lead_in.size());
  lead_in.insert(lead_in.end(), pts.begin(), pts.end());
  // Step 5: padding (with the insertion-index bug fixed). Never consumes the generator for the shipped
  // characters; the fixed seed keeps it deterministic for other drawings.
  Rng padding_rng(0);
  out.points = pad_to_min_points(std::move(lead_in), kMinCharacterPoints, padding_rng);
  return out;
}

Glyph classic_glyph(char symbol, const StrokeDrawing& drawing, std::string source) {
  Glyph g{symbol, std::move(source), {}};
  append_differences(classic_character_points(drawing, g.source).points, true, g.steps);
  return g;
}

Glyph balinese_glyph(char symbol, const StrokeDrawing& drawing, std::string source) {
  std::vector<std::vector<Point2>> strokes;
  double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
  for (const auto& stroke : drawing.strokes) {
    strokes.push_back(image_points(stroke));
    for (const auto& p : strokes.back()) {
      min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
    }
  }
  const double extent = std::max(max_x - min_x, max_y - min_y);
  if (strokes.empty() || !(extent > 0.0)) throw InputError(source, "drawing has zero extent");
  const double scale = kScaleWidth / extent;
  for (auto& stroke : strokes) {
    for (auto& p : stroke) p = {(p.x - min_x) * scale, (p.y - max_y) * scale};
    stroke = infill_reference(stroke);
  }
  Glyph g{symbol, std::move(source), {}};
  Point2 pen{0.0, 0.0};
  for (const auto& stroke : strokes) {
    append_pen_up_move(pen, stroke.front(), g.steps);
    if (stroke.size() == 1) g.steps.push_back({0.0, 0.0, true});  // a dot
    append_differences(stroke, true, g.steps);
    pen = stroke.back();
  }
  append_pen_up_move(pen, {(max_x - min_x) * scale, 0.0}, g.steps);
  return g;
}

Glyph connector_glyph(char symbol) {
  Glyph g{symbol, "connector", {}};
  if (symbol == '-') {
    g.steps.assign(20, {1.0, 0.0, true});
  } else if (symbol == '^') {
    g.steps.assign(20, {1.0, -2.0, true});
    g.steps.insert(g.steps.end(), 20, {1.0, 2.0, true});
  } else {
    throw std::invalid_argument(std::string("connector_glyph: not a connector: ") + symbol);
  }
  return g;
}

}  // namespace sc::writing
