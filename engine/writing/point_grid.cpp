#include "engine/writing/point_grid.hpp"

#include <algorithm>
#include <cmath>

namespace sc::writing {
namespace {

std::int64_t key(std::int64_t cx, std::int64_t cy) { return cx * 0x100000001LL + cy; }

}  // namespace

PointGrid::PointGrid(const std::vector<Point2>& points, double cell) : points_(points), cell_(cell) {
  for (std::size_t i = 0; i < points.size(); ++i) cells_[key(cell_of(points[i].x), cell_of(points[i].y))].push_back(i);
}

std::int64_t PointGrid::cell_of(double v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }

double PointGrid::nearest(const Point2& q, double good_enough) const {
  const std::int64_t cx = cell_of(q.x), cy = cell_of(q.y);
  double best2 = INFINITY;
  const double good2 = good_enough * good_enough;
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      const auto it = cells_.find(key(cx + dx, cy + dy));
      if (it == cells_.end()) continue;
      for (std::size_t i : it->second) {
        const double ex = points_[i].x - q.x, ey = points_[i].y - q.y;
        best2 = std::min(best2, ex * ex + ey * ey);
        if (best2 <= good2) return std::sqrt(best2);
      }
    }
  return best2 <= cell_ * cell_ ? std::sqrt(best2) : INFINITY;
}

}  // namespace sc::writing
