#include "teaching/skills/phase_vote.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <tuple>

namespace sc {

namespace {

std::vector<int> phase_boundaries(const Segmentation& s) {
  std::vector<int> out;
  for (const SkillSegment& seg : s.segments)
    if (seg.begin > 0) out.push_back(seg.begin);
  return out;
}

struct VotedBoundary {
  int support = 0;
  int spread = 0;
  int position = 0;
  bool operator<(const VotedBoundary& o) const {
    return std::tie(o.support, spread, position) < std::tie(support, o.spread, o.position);
  }
};

VotedBoundary vote_on(int position, const std::vector<std::vector<int>>& boundaries, int tolerance) {
  VotedBoundary c{0, 0, position};
  for (const std::vector<int>& phase : boundaries) {
    int nearest = tolerance + 1;
    for (int b : phase) nearest = std::min(nearest, std::abs(b - position));
    if (nearest > tolerance) continue;
    ++c.support;
    c.spread += nearest;
  }
  return c;
}

std::vector<int> voted_boundaries(const std::vector<std::vector<int>>& boundaries, int tolerance) {
  std::vector<VotedBoundary> candidates;
  for (const std::vector<int>& phase : boundaries)
    for (int b : phase) candidates.push_back(vote_on(b, boundaries, tolerance));
  std::sort(candidates.begin(), candidates.end());
  std::vector<int> kept;
  for (const VotedBoundary& c : candidates) {
    if (2 * c.support <= static_cast<int>(boundaries.size())) break;
    const bool clash =
        std::any_of(kept.begin(), kept.end(), [&](int k) { return std::abs(k - c.position) <= tolerance; });
    if (!clash) kept.push_back(c.position);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The skill the phases give most of [begin, end), counted over actions and phases; ties to the lowest id.
int voted_skill(const std::vector<Segmentation>& phases, int begin, int end) {
  std::map<int, int> actions;
  for (const Segmentation& phase : phases)
    for (const SkillSegment& s : phase.segments) {
      const int overlap = std::min(end, s.end) - std::max(begin, s.begin);
      if (overlap > 0) actions[s.skill] += overlap;
    }
  int best = 0, most = 0;
  for (const auto& [skill, n] : actions)
    if (n > most) best = skill, most = n;
  return best;
}

}  // namespace

Segmentation vote_phases(const std::vector<Segmentation>& phases, int length, int tolerance) {
  std::vector<std::vector<int>> boundaries;
  for (const Segmentation& s : phases) boundaries.push_back(phase_boundaries(s));
  std::vector<int> edges{0};
  for (int b : voted_boundaries(boundaries, tolerance))
    if (b < length) edges.push_back(b);
  edges.push_back(length);
  Segmentation out;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    if (edges[k + 1] > edges[k])
      out.segments.push_back({voted_skill(phases, edges[k], edges[k + 1]), edges[k], edges[k + 1]});
  return out;
}

int phase_vote_tolerance(int actions, int model_steps) {
  if (model_steps <= 0) return 1;
  return std::max(1, (actions + model_steps - 1) / model_steps);
}

}  // namespace sc
