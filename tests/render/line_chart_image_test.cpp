// The line chart draws each series in its colour where its points lie, the reference line across the
// panel, and keeps a higher value above a lower one (the value axis grows upwards).
#include "engine/render/line_chart_image.hpp"

#include <cstdlib>

#include <gtest/gtest.h>

#include "engine/render/gl_context.hpp"

namespace sc {
namespace {

bool near_colour(const std::uint8_t* p, int r, int g, int b) {
  return std::abs(p[0] - r) < 12 && std::abs(p[1] - g) < 12 && std::abs(p[2] - b) < 12;
}

// Rows (top first) below the title and legend in which column x holds the colour.
std::vector<int> rows_of(const RgbaImage& image, int x, int r, int g, int b) {
  std::vector<int> rows;
  for (int y = 100; y < image.height; ++y)
    if (near_colour(image.at(x, y), r, g, b)) rows.push_back(y);
  return rows;
}

TEST(LineChartImage, SeriesRisesWithItsValuesAndTheReferenceSpansThePanel) {
  LineChartFigure figure;
  figure.title = "curve";
  figure.x_label = "epochs";
  figure.width = 640;
  figure.height = 400;
  figure.panels = {{"reward",
                    "%.1f",
                    {{"student", Color::hex(0xe0833a), {0, 10}, {-1.0, -0.2}}},
                    {{"expert", Color::hex(0x3a8f5c), -0.1}}}};
  auto context = create_offscreen_context(offscreen_backend_from_env(), figure.width, figure.height);
  const RgbaImage image = render_line_chart_figure(*context, figure);
  ASSERT_EQ(image.width, 640);
  ASSERT_EQ(image.height, 400);
  // The rising line: its pixels near the left end lie lower (larger y) than near the right end.
  const std::vector<int> left = rows_of(image, 140, 0xe0, 0x83, 0x3a);
  const std::vector<int> right = rows_of(image, 560, 0xe0, 0x83, 0x3a);
  ASSERT_FALSE(left.empty());
  ASSERT_FALSE(right.empty());
  EXPECT_GT(left.front(), right.front());
  // The dashed expert line above both, found somewhere across the panel's width.
  int dashes = 0, row = -1;
  for (int x = 100; x < 600; x += 3) {
    const std::vector<int> rows = rows_of(image, x, 0x3a, 0x8f, 0x5c);
    if (rows.empty()) continue;
    ++dashes;
    row = rows.front();
  }
  EXPECT_GT(dashes, 40);
  EXPECT_LT(row, right.front());
}

}  // namespace
}  // namespace sc
