#pragma once
// Writing drills made playable: the segments' pen moves are chained so each segment starts where the
// previous one ended (no jumps), the chain starts at the first segment's original position on the
// canvas, and the whole path is shifted back inside the 500 x 300 canvas when it leaves it (a path wider
// than the canvas keeps its left/top edge inside). Pen flags (3-D balinese actions) are kept.
#include <vector>

#include "engine/writing/trace_point.hpp"
#include "teaching/drills/drill_plan.hpp"

namespace sc {

class WritingDrillProjector final : public DrillProjector {
 public:
  // experts[i]: expert i's writing step sequence (states [x, y, timer, goal...], actions (dx, dy[, pen])).
  explicit WritingDrillProjector(std::vector<StepSequence> experts);

  // steps: the expert states with x, y replaced by the stitched pen position and the timer by the drill's
  // own step index; ghost_path: pen positions (px) incl. the final one; drill_return 0 and success true:
  // the stitched path is its own gold, which the expert traces exactly.
  PlayableDrill project(const DrillPlan& plan) const override;

  // The drill's pen path as a trace (ghost_path with the pen flags of its actions).
  static std::vector<writing::TracePoint> drill_trace(const PlayableDrill& drill);

 private:
  std::vector<StepSequence> experts_;
};

}  // namespace sc
