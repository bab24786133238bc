#include "engine/writing_view/scripted_trace.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/rng.hpp"

namespace sc::writing_view {

std::vector<writing::TracePoint> scripted_learner_trace(std::span<const writing::TracePoint> gold,
                                                        const ScriptedHand& hand) {
  std::vector<writing::TracePoint> out;
  if (gold.empty()) return out;
  const std::size_t stride = std::max<std::size_t>(1, hand.stride);
  const double fraction = std::clamp(hand.fraction, 0.0, 1.0);
  const std::size_t last = static_cast<std::size_t>(std::lround(fraction * static_cast<double>(gold.size() - 1)));
  Rng rng(hand.seed);
  const double two_pi = 2.0 * std::numbers::pi;
  const double phase[4] = {rng.uniform(0, two_pi), rng.uniform(0, two_pi), rng.uniform(0, two_pi),
                           rng.uniform(0, two_pi)};
  // Periods in gold steps (about px): a slow drift and a faster tremble.
  const auto wobble = [&](std::size_t i) {
    const double s = static_cast<double>(i);
    const double dx = 0.7 * std::sin(s / 41.0 + phase[0]) + 0.3 * std::sin(s / 9.0 + phase[1]);
    const double dy = 0.7 * std::sin(s / 53.0 + phase[2]) + 0.3 * std::sin(s / 11.0 + phase[3]);
    return std::pair{hand.wobble_px * dx, hand.wobble_px * dy};
  };
  for (std::size_t i = 0; i <= last; ++i) {
    const bool pen_changes = i + 1 <= last && gold[i + 1].pen != gold[i].pen;
    if (i % stride != 0 && i != last && !pen_changes) continue;
    const auto [dx, dy] = wobble(i);
    // The pen state of a kept point is that of the gold step into it; a skipped pen-up step before a kept
    // pen-down point would otherwise turn a hop into ink, so every point where the pen changes is kept.
    out.push_back({gold[i].x + dx, gold[i].y + dy, gold[i].pen});
  }
  return out;
}

}  // namespace sc::writing_view
