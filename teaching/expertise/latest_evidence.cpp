#include "teaching/expertise/latest_evidence.hpp"

#include <string>

#include "engine/core/error.hpp"

namespace sc {

ExpertiseEstimate latest_evidence_expertise(const std::vector<ExpertiseEstimate>& rounds, int num_targets) {
  ExpertiseEstimate out;
  if (rounds.empty()) {
    rank_expertise(out, num_targets);
    return out;
  }
  const int skills = rounds.front().num_skills();
  for (std::size_t r = 0; r < rounds.size(); ++r) {
    if (rounds[r].num_skills() != skills) {
      throw InputError("adaptive expertise", "round " + std::to_string(r) + " has " +
                                                 std::to_string(rounds[r].num_skills()) + " skills, round 0 has " +
                                                 std::to_string(skills));
    }
  }
  const auto n = static_cast<std::size_t>(skills);
  out.expertise.assign(n, 0.0);
  out.occurrences.assign(n, 0);
  out.contributions.assign(n, {});
  for (std::size_t m = 0; m < n; ++m) {
    for (auto r = rounds.rbegin(); r != rounds.rend(); ++r) {
      const int occ = r->occurrences[m];
      if (occ == 0) continue;
      out.expertise[m] = r->expertise[m] / occ;
      out.occurrences[m] = occ;
      out.contributions[m] = r->contributions[m];
      break;
    }
  }
  rank_expertise(out, num_targets);
  return out;
}

}  // namespace sc
