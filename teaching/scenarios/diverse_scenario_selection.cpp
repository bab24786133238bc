#include "teaching/scenarios/diverse_scenario_selection.hpp"

#include <map>
#include <set>
#include <tuple>
#include <utility>

#include "engine/core/error.hpp"

namespace sc {
namespace {

using Bigram = std::pair<int, int>;

struct Candidate {
  std::set<int> skills;
  std::set<Bigram> bigrams;
};

Candidate describe(const Segmentation& seg) {
  Candidate c;
  const std::vector<int> ids = seg.skills();
  for (std::size_t i = 0; i < ids.size(); ++i) {
    c.skills.insert(ids[i]);
    if (i + 1 < ids.size()) c.bigrams.insert({ids[i], ids[i + 1]});
  }
  return c;
}

ScenarioPick score(int index, const Candidate& c, const std::map<int, int>& times_shown,
                   const std::set<Bigram>& shown_bigrams) {
  ScenarioPick p;
  p.scenario = index;
  for (int m : c.skills) {
    const auto it = times_shown.find(m);
    if (it == times_shown.end()) {
      ++p.new_skills;
    } else {
      p.redundancy += it->second;
    }
  }
  for (const Bigram& b : c.bigrams) p.new_bigrams += shown_bigrams.count(b) == 0 ? 1 : 0;
  return p;
}

// True when a should be picked before b (criteria documented in the header).
bool better(const ScenarioPick& a, const ScenarioPick& b) {
  return std::make_tuple(a.new_skills, a.new_bigrams, -a.redundancy, -a.scenario) >
         std::make_tuple(b.new_skills, b.new_bigrams, -b.redundancy, -b.scenario);
}

}  // namespace

std::vector<int> ScenarioSelection::scenarios() const {
  std::vector<int> out;
  out.reserve(picks.size());
  for (const auto& p : picks) out.push_back(p.scenario);
  return out;
}

ScenarioSelection select_diverse_scenarios(const std::vector<Segmentation>& expert_pool, int count) {
  if (count < 0) throw InputError("diverse scenario selection", "the number of scenarios must be >= 0");
  std::vector<Candidate> candidates;
  candidates.reserve(expert_pool.size());
  for (const auto& seg : expert_pool) candidates.push_back(describe(seg));

  const int n = static_cast<int>(expert_pool.size());
  const int wanted = count < n ? count : n;
  std::vector<bool> used(expert_pool.size(), false);
  std::map<int, int> times_shown;  // skill -> number of picks that showed it
  std::set<Bigram> shown_bigrams;
  ScenarioSelection out;
  for (int k = 0; k < wanted; ++k) {
    ScenarioPick best;
    bool have = false;
    for (int i = 0; i < n; ++i) {
      if (used[static_cast<std::size_t>(i)]) continue;
      const ScenarioPick p = score(i, candidates[static_cast<std::size_t>(i)], times_shown, shown_bigrams);
      if (!have || better(p, best)) {
        best = p;
        have = true;
      }
    }
    used[static_cast<std::size_t>(best.scenario)] = true;
    const Candidate& c = candidates[static_cast<std::size_t>(best.scenario)];
    for (int m : c.skills) ++times_shown[m];
    shown_bigrams.insert(c.bigrams.begin(), c.bigrams.end());
    out.picks.push_back(best);
  }
  for (const auto& [skill, times] : times_shown) out.covered_skills.push_back(skill);
  return out;
}

}  // namespace sc
