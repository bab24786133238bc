#include "teaching/skills/restart_choice.hpp"

#include <algorithm>
#include <cmath>

namespace sc {

std::size_t choose_restart(const std::vector<RestartOutcome>& runs) {
  bool units = true;
  double lowest_unit_term = INFINITY;
  for (const RestartOutcome& run : runs) {
    units = units && std::isfinite(run.unit_term);
    if (std::isfinite(run.unit_term)) lowest_unit_term = std::min(lowest_unit_term, run.unit_term);
  }
  auto candidate = [&](const RestartOutcome& run) {
    return !units || run.unit_term <= lowest_unit_term + kUnitTermSlack;
  };
  bool scored = true;
  for (const RestartOutcome& run : runs)
    if (candidate(run)) scored = scored && std::isfinite(run.score);
  auto better = [&](const RestartOutcome& a, const RestartOutcome& b) {
    if (scored && a.score != b.score) return a.score > b.score;
    return a.valid_nll < b.valid_nll;
  };
  std::size_t kept = runs.size();
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (!candidate(runs[r])) continue;
    if (kept == runs.size() || better(runs[r], runs[kept])) kept = r;
  }
  return kept;
}

}  // namespace sc
