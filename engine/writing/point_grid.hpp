#pragma once
// Nearest-point queries over a fixed set of ink points, for scores that only care about points within a
// cutoff: the writing score's recall and precision, and the execution score of one letter
// (teaching/tasks/writing_execution.cpp). A scan of every point made those quadratic in the ink's length.
//
// Spec: points are bucketed into square cells of side `cell`, so every point within `cell` of a query lies in
// the 3 x 3 block of cells around the query's cell. nearest(q, good_enough) is the distance to the nearest
// point if it is within `cell` (+inf otherwise); it may stop at the first point within `good_enough`.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "engine/writing/trace_point.hpp"

namespace sc::writing {

class PointGrid {
 public:
  // Keeps a reference to `points`: they must outlive the grid.
  PointGrid(const std::vector<Point2>& points, double cell);

  double nearest(const Point2& q, double good_enough) const;

 private:
  std::int64_t cell_of(double v) const;

  const std::vector<Point2>& points_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

}  // namespace sc::writing
