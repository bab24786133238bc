#include "teaching/skills/repeat_boundaries.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>

#include "engine/core/error.hpp"

namespace sc {

namespace {

constexpr int kEdgeToken = -1;  // "before the start" / "after the end" as a neighbour
constexpr std::uint64_t kBase = 0x100000001b3ULL;

// Token ids by rounded coordinates, in order of first appearance (so ids do not depend on hashing).
std::vector<std::vector<int>> tokenize(const std::vector<StepSequence>& demos, double precision) {
  std::map<std::vector<long long>, int> ids;
  std::vector<std::vector<int>> out;
  for (const auto& d : demos) {
    std::vector<int> tokens;
    for (int t = 0; t < d.length(); ++t) {
      std::vector<long long> key;
      for (int a = 0; a < d.action_dim; ++a)
        key.push_back(std::llround(d.actions[static_cast<std::size_t>(t * d.action_dim + a)] / precision));
      tokens.push_back(ids.emplace(std::move(key), static_cast<int>(ids.size())).first->second);
    }
    out.push_back(std::move(tokens));
  }
  return out;
}

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Polynomial hashes of every window of one demonstration's tokens.
class WindowHash {
 public:
  explicit WindowHash(const std::vector<int>& tokens) : prefix_(tokens.size() + 1, 0), power_(tokens.size() + 1, 1) {
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      prefix_[i + 1] = prefix_[i] * kBase + static_cast<std::uint64_t>(tokens[i] + 2);
      power_[i + 1] = power_[i] * kBase;
    }
  }
  // Key of tokens [begin, end): the hash mixed with the length, so clipped windows differ from full ones.
  std::uint64_t key(std::size_t begin, std::size_t end) const {
    const std::uint64_t h = prefix_[end] - prefix_[begin] * power_[end - begin];
    return mix(h ^ mix(static_cast<std::uint64_t>(end - begin) + 0x9e3779b97f4a7c15ULL));
  }

 private:
  std::vector<std::uint64_t> prefix_, power_;
};

// Distinct neighbour tokens seen for each context key (a handful at most, so a small vector).
class Variety {
 public:
  void add(std::uint64_t key, int neighbour) {
    auto& seen = table_[key];
    if (std::find(seen.begin(), seen.end(), neighbour) == seen.end()) seen.push_back(neighbour);
  }
  int count(std::uint64_t key) const {
    const auto it = table_.find(key);
    return it == table_.end() ? 0 : static_cast<int>(it->second.size());
  }

 private:
  std::unordered_map<std::uint64_t, std::vector<int>> table_;
};

struct Candidate {
  int position = 0;
  int forward = 0, backward = 0;
  bool both() const { return forward > 1 && backward > 1; }
};

std::vector<int> strongest(std::vector<Candidate> candidates, const RepeatBoundaryConfig& config) {
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if ((a.backward > 1) != (b.backward > 1)) return a.backward > 1;
    if (a.both() != b.both()) return a.both();
    if (a.forward + a.backward != b.forward + b.backward) return a.forward + a.backward > b.forward + b.backward;
    return a.position < b.position;
  });
  std::vector<int> kept;
  for (const auto& c : candidates) {
    if (static_cast<int>(kept.size()) >= config.max_boundaries) break;
    const bool far =
        std::all_of(kept.begin(), kept.end(), [&](int k) { return std::abs(k - c.position) >= config.min_separation; });
    if (far) kept.push_back(c.position);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace

std::vector<std::vector<int>> find_repeat_boundaries(const std::vector<StepSequence>& demos,
                                                     const RepeatBoundaryConfig& config) {
  if (config.context < 1 || config.max_boundaries < 0 || config.min_separation < 1 || !(config.token_precision > 0.0))
    throw InputError("repeat boundaries",
                     "context and min_separation must be >= 1, max_boundaries >= 0, precision > 0");
  const auto tokens = tokenize(demos, config.token_precision);
  const auto n = static_cast<std::size_t>(config.context);
  std::vector<WindowHash> hashes;
  Variety forward, backward;
  for (const auto& tok : tokens) {
    hashes.emplace_back(tok);
    const WindowHash& h = hashes.back();
    const std::size_t t_len = tok.size();
    for (std::size_t p = 1; p <= t_len; ++p)  // the context before p and what follows it (the end, at p = T)
      forward.add(h.key(p > n ? p - n : 0, p), p < t_len ? tok[p] : kEdgeToken);
    for (std::size_t p = 0; p < t_len; ++p)  // the context from p on and what precedes it
      backward.add(h.key(p, std::min(t_len, p + n)), p > 0 ? tok[p - 1] : kEdgeToken);
  }
  std::vector<std::vector<int>> out;
  for (std::size_t d = 0; d < tokens.size(); ++d) {
    const std::size_t t_len = tokens[d].size();
    std::vector<Candidate> candidates;
    for (std::size_t p = 1; p < t_len; ++p) {
      Candidate c{static_cast<int>(p), forward.count(hashes[d].key(p > n ? p - n : 0, p)),
                  backward.count(hashes[d].key(p, std::min(t_len, p + n)))};
      if (c.forward > 1 || c.backward > 1) candidates.push_back(c);
    }
    out.push_back(strongest(std::move(candidates), config));
  }
  return out;
}

std::vector<std::vector<int>> repeat_units(const std::vector<StepSequence>& demos,
                                           const std::vector<std::vector<int>>& boundaries, int max_units,
                                           double token_precision) {
  if (boundaries.size() != demos.size())
    throw InputError("repeat units", std::to_string(boundaries.size()) + " boundary lists for " +
                                         std::to_string(demos.size()) + " demonstrations");
  if (max_units < 0 || !(token_precision > 0.0))
    throw InputError("repeat units", "max_units must be >= 0 and the precision > 0");
  const auto tokens = tokenize(demos, token_precision);
  struct Unit {
    int count = 0, first = 0;  // occurrences; order of first appearance
    int id = -1;
  };
  std::map<std::vector<int>, Unit> units_by_steps;
  std::vector<std::vector<Unit*>> segments(demos.size());
  for (std::size_t d = 0; d < demos.size(); ++d) {
    std::size_t begin = 0;
    for (std::size_t j = 0; j <= boundaries[d].size(); ++j) {
      const std::size_t end = j < boundaries[d].size() ? static_cast<std::size_t>(boundaries[d][j]) : tokens[d].size();
      if (end < begin || end > tokens[d].size())
        throw InputError("repeat units", "boundaries of demonstration " + std::to_string(d) + " are not ascending");
      std::vector<int> steps(tokens[d].begin() + static_cast<std::ptrdiff_t>(begin),
                             tokens[d].begin() + static_cast<std::ptrdiff_t>(end));
      Unit& unit =
          units_by_steps.emplace(std::move(steps), Unit{0, static_cast<int>(units_by_steps.size())}).first->second;
      ++unit.count;
      segments[d].push_back(&unit);
      begin = end;
    }
  }
  std::vector<Unit*> repeated;
  for (auto& entry : units_by_steps)
    if (entry.second.count >= 2) repeated.push_back(&entry.second);
  std::sort(repeated.begin(), repeated.end(), [](const Unit* a, const Unit* b) {
    return a->count != b->count ? a->count > b->count : a->first < b->first;
  });
  for (std::size_t u = 0; u < repeated.size() && u < static_cast<std::size_t>(max_units); ++u)
    repeated[u]->id = static_cast<int>(u);
  std::vector<std::vector<int>> out;
  for (const auto& row : segments) {
    std::vector<int> units;
    for (const Unit* unit : row) units.push_back(unit->id);
    out.push_back(std::move(units));
  }
  return out;
}

}  // namespace sc
