// The classic characters and connectors reproduce the reference's preprocessed data (reference-facts §2.4).
#include "engine/writing/glyph.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/writing/alphabet.hpp"

namespace sc::writing {
namespace {

struct Expected {
  char symbol;
  int lead_in;
  int actions;
  double net_dx, net_dy;
  double y_min, y_max;
};

// reference-facts §2.4 table (printed with 2-3 decimals, hence the tolerances below).
constexpr Expected kTable[] = {{'a', 39, 724, 95.918, 0.332, -44.57, 0.33}, {'b', 25, 409, 100.0, 0.854, -25.03, 32.62},
                               {'c', 53, 635, 98.611, 0.980, -69.85, 0.98}, {'t', 42, 640, 100.0, 0.631, -59.11, 4.53},
                               {'e', 49, 521, 100.0, 0.190, -83.42, 0.19},  {'-', 0, 20, 20.0, 0.0, 0.0, 0.0},
                               {'^', 0, 40, 40.0, 0.0, -40.0, 0.0}};

struct Summary {
  double dx = 0, dy = 0, y_min = 0, y_max = 0;
};

Summary summarize(const Glyph& g) {
  Summary s;
  for (const auto& step : g.steps) {
    s.dx += step.dx;
    s.dy += step.dy;
    s.y_min = std::min(s.y_min, s.dy);
    s.y_max = std::max(s.y_max, s.dy);
  }
  return s;
}

TEST(ClassicGlyphs, ReproduceReferenceTable) {
  const GlyphSet set = GlyphSet::load(AlphabetKind::Classic, omniglot_data_dir());
  for (const auto& e : kTable) {
    SCOPED_TRACE(std::string("symbol ") + e.symbol);
    const Glyph& g = set.glyph(e.symbol);
    EXPECT_EQ(static_cast<int>(g.steps.size()), e.actions);
    const Summary s = summarize(g);
    EXPECT_NEAR(s.dx, e.net_dx, 6e-4);
    EXPECT_NEAR(s.dy, e.net_dy, 6e-4);
    EXPECT_NEAR(s.y_min, e.y_min, 6e-3);
    EXPECT_NEAR(s.y_max, e.y_max, 6e-3);
    for (const auto& step : g.steps) EXPECT_TRUE(step.pen);
  }
}

TEST(ClassicGlyphs, LeadInAndInfillRules) {
  const auto data = omniglot_data_dir();
  for (const auto& e : kTable) {
    if (is_connector(e.symbol)) continue;
    SCOPED_TRACE(std::string("symbol ") + e.symbol);
    const auto drawing = read_stroke_file(data / stroke_file_name(character_number(AlphabetKind::Classic, e.symbol),
                                                                  default_drawer(AlphabetKind::Classic, e.symbol)));
    const auto pts = classic_character_points(drawing);
    EXPECT_EQ(pts.lead_in_points, e.lead_in);
    ASSERT_EQ(static_cast<int>(pts.points.size()), e.actions + 1);
    // Every step is Chebyshev <= 1 px; the lead-in is a straight climb along x = x_first in 1 px steps.
    for (std::size_t i = 1; i < pts.points.size(); ++i) {
      EXPECT_LE(std::fabs(pts.points[i].x - pts.points[i - 1].x), 1.0);
      EXPECT_LE(std::fabs(pts.points[i].y - pts.points[i - 1].y), 1.0);
    }
    for (int i = 0; i < e.lead_in; ++i) {
      EXPECT_EQ(pts.points[i].x, pts.points[e.lead_in].x);
      if (i > 0) {
        EXPECT_EQ(pts.points[i].y - pts.points[i - 1].y, -1.0);
      }
    }
    // Net vertical drift y_last - (ceil(y_last) - 1) lies in (0, 1].
    const double drift = pts.points.back().y - pts.points.front().y;
    EXPECT_GT(drift, 0.0);
    EXPECT_LE(drift, 1.0);
    // The stroke is exactly 100 px wide.
    auto [lo, hi] =
        std::minmax_element(pts.points.begin(), pts.points.end(), [](auto& a, auto& b) { return a.x < b.x; });
    EXPECT_NEAR(hi->x - lo->x, 100.0, 1e-9);
  }
}

TEST(ClassicGlyphs, FirstActionsAreTheLeadInAndAHasOneZeroAction) {
  const GlyphSet set = GlyphSet::load(AlphabetKind::Classic, omniglot_data_dir());
  for (char c : std::string("abcte")) {
    EXPECT_EQ(set.glyph(c).steps.front(), (WritingStep{0.0, -1.0, true})) << c;
  }
  const auto& a = set.glyph('a').steps;
  EXPECT_EQ(std::count_if(a.begin(), a.end(), [](const WritingStep& s) { return s.dx == 0 && s.dy == 0; }), 1);
}

TEST(ClassicGlyphs, ZeroWidthStrokeIsAnInputErrorNamingTheFile) {
  StrokeDrawing vertical;
  vertical.strokes.push_back({{5, 0, 0}, {5, 10, 1}});
  try {
    classic_character_points(vertical, "x/0000_01.txt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "x/0000_01.txt: first stroke has zero width");
  }
}

TEST(ConnectorGlyphs, ShapesAndErrors) {
  const Glyph dash = connector_glyph('-');
  ASSERT_EQ(dash.steps.size(), 20u);
  EXPECT_EQ(dash.steps[7], (WritingStep{1, 0, true}));
  const Glyph hat = connector_glyph('^');
  ASSERT_EQ(hat.steps.size(), 40u);
  EXPECT_EQ(hat.steps[19], (WritingStep{1, -2, true}));
  EXPECT_EQ(hat.steps[20], (WritingStep{1, 2, true}));
  EXPECT_THROW(connector_glyph('a'), std::invalid_argument);
}

TEST(BalineseGlyph, MultiStrokeHasPenUpMovesAndFitsTheBox) {
  // character01 drawer 08 has nine strokes.
  const auto drawing = read_stroke_file(omniglot_data_dir() / stroke_file_name(1, 8));
  ASSERT_EQ(drawing.strokes.size(), 9u);
  const Glyph g = balinese_glyph('A', drawing, "character01/0108_08.txt");
  double x = 0, y = 0, min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  int pen_runs = 0;
  bool previous_pen = false;
  for (const auto& s : g.steps) {
    EXPECT_LE(std::fabs(s.dx), 1.0);
    EXPECT_LE(std::fabs(s.dy), 1.0);
    x += s.dx, y += s.dy;
    if (s.pen) {
      min_x = std::min(min_x, x), max_x = std::max(max_x, x), min_y = std::min(min_y, y), max_y = std::max(max_y, y);
    }
    if (s.pen && !previous_pen) ++pen_runs;
    previous_pen = s.pen;
  }
  EXPECT_EQ(pen_runs, 9);             // one inked run per stroke
  EXPECT_FALSE(g.steps.front().pen);  // enters lifted
  EXPECT_FALSE(g.steps.back().pen);   // leaves lifted, back on the baseline
  EXPECT_NEAR(y, 0.0, 1e-9);
  EXPECT_NEAR(x, max_x, 1.0);  // exit at the right edge of the ink
  EXPECT_LE(std::max(max_x - min_x, max_y - min_y), 100.0 + 1e-9);
  EXPECT_GE(std::max(max_x - min_x, max_y - min_y), 99.0);
  EXPECT_LE(max_y, 1e-9);  // ink sits on or above the baseline
}

TEST(BalineseGlyph, DotStrokeIsOneZeroLengthInkedStep) {
  StrokeDrawing d;
  d.strokes.push_back({{0, 0, 0}, {50, 0, 10}});
  d.strokes.push_back({{25, 20, 20}});  // a dot below the line (motor y up)
  const Glyph g = balinese_glyph('A', d, "test");
  const auto dots = std::count_if(g.steps.begin(), g.steps.end(),
                                  [](const WritingStep& s) { return s.pen && s.dx == 0 && s.dy == 0; });
  EXPECT_EQ(dots, 1);
}

}  // namespace
}  // namespace sc::writing
