#pragma once
// A deterministic stand-in for a learner's hand: the gold path, sampled like a mouse (every `stride`-th
// point) and displaced by a smooth wobble (a sum of two sinusoids along the path per axis, random phases from
// the seed). Headless screenshots and golden images show it instead of real input, so they are reproducible.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/writing/trace_point.hpp"

namespace sc::writing_view {

struct ScriptedHand {
  std::uint64_t seed = 1;
  double wobble_px = 2.5;  // amplitude of the displacement on each axis
  std::size_t stride = 4;  // keep every stride-th gold point (the gold moves <= 1 px per step)
  double fraction = 1.0;   // how much of the gold path (by points) is written, in [0, 1]
};

// Pen flags follow the gold (pen-up moves stay pen-up). The first and last kept points are the gold's own
// points of that range, so a pen-up/pen-down boundary is never skipped: every gold point where the pen state
// changes is kept.
std::vector<writing::TracePoint> scripted_learner_trace(std::span<const writing::TracePoint> gold,
                                                        const ScriptedHand& hand);

}  // namespace sc::writing_view
