#include "teaching/students/bc_datasets.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/core/rng.hpp"

namespace sc {
namespace {

void append_steps(BcDataset& out, const StepSequence& s, const std::string& where) {
  if (s.length() == 0) return;
  if (out.size() == 0 && out.state_dim == 0) {
    out.state_dim = s.state_dim;
    out.action_dim = s.action_dim;
  }
  if (s.state_dim != out.state_dim || s.action_dim != out.action_dim)
    throw InputError(where, "state/action dimensions differ from the first sequence's");
  const std::size_t t = static_cast<std::size_t>(s.length());
  out.states.insert(out.states.end(), s.states.begin(), s.states.begin() + static_cast<long>(t * s.state_dim));
  out.actions.insert(out.actions.end(), s.actions.begin(), s.actions.end());
}

bool is_reverse(const BcDataset& data, int i) {
  return data.actions[static_cast<std::size_t>(i) * static_cast<std::size_t>(data.action_dim)] < 0.0f;
}

BcDataset empty_like(const BcDataset& data) {
  BcDataset out;
  out.state_dim = data.state_dim;
  out.action_dim = data.action_dim;
  return out;
}

void copy_pair(const BcDataset& from, int i, BcDataset& to) {
  const auto s = static_cast<std::size_t>(i) * static_cast<std::size_t>(from.state_dim);
  const auto a = static_cast<std::size_t>(i) * static_cast<std::size_t>(from.action_dim);
  to.states.insert(to.states.end(), from.states.begin() + static_cast<long>(s),
                   from.states.begin() + static_cast<long>(s + static_cast<std::size_t>(from.state_dim)));
  to.actions.insert(to.actions.end(), from.actions.begin() + static_cast<long>(a),
                    from.actions.begin() + static_cast<long>(a + static_cast<std::size_t>(from.action_dim)));
}

}  // namespace

BcDataset bc_dataset_from_steps(const std::vector<StepSequence>& sequences) {
  BcDataset out;
  for (std::size_t i = 0; i < sequences.size(); ++i) append_steps(out, sequences[i], "sequence " + std::to_string(i));
  return out;
}

BcDataset bc_dataset_from_plan(const DrillPlan& plan, const std::vector<StepSequence>& experts) {
  return bc_dataset_from_steps({concatenate_expert_steps(plan, experts)});
}

int count_reverse_pairs(const BcDataset& data) {
  int count = 0;
  for (int i = 0; i < data.size(); ++i) count += is_reverse(data, i);
  return count;
}

namespace {

// The first `count` candidates after a partial Fisher-Yates shuffle with our RNG: a uniform sample without
// replacement.
std::vector<int> uniform_sample(std::vector<int> candidates, std::size_t count, std::uint64_t seed) {
  count = std::min(count, candidates.size());
  Rng rng(seed);
  for (std::size_t i = 0; i < count; ++i)
    std::swap(candidates[i], candidates[i + static_cast<std::size_t>(rng.below(candidates.size() - i))]);
  candidates.resize(count);
  return candidates;
}

// The marked pairs, in their original order.
BcDataset pairs_where(const BcDataset& data, const std::vector<bool>& keep) {
  BcDataset out = empty_like(data);
  for (int i = 0; i < data.size(); ++i)
    if (keep[static_cast<std::size_t>(i)]) copy_pair(data, i, out);
  return out;
}

}  // namespace

BcDataset keep_reverse_fraction(const BcDataset& data, double keep_fraction, std::uint64_t seed) {
  if (!(keep_fraction >= 0.0 && keep_fraction <= 1.0))
    throw InputError("reverse-action filter", "keep fraction must lie in [0, 1], got " + std::to_string(keep_fraction));
  std::vector<int> reverse;
  for (int i = 0; i < data.size(); ++i)
    if (is_reverse(data, i)) reverse.push_back(i);
  const auto keep = static_cast<std::size_t>(std::lround(keep_fraction * static_cast<double>(reverse.size())));
  std::vector<bool> kept(static_cast<std::size_t>(data.size()), true);
  for (int i : reverse) kept[static_cast<std::size_t>(i)] = false;
  for (int i : uniform_sample(reverse, keep, seed)) kept[static_cast<std::size_t>(i)] = true;
  return pairs_where(data, kept);
}

BcDataset sample_pairs(const BcDataset& data, int count, std::uint64_t seed) {
  std::vector<int> all(static_cast<std::size_t>(data.size()));
  for (int i = 0; i < data.size(); ++i) all[static_cast<std::size_t>(i)] = i;
  std::vector<bool> kept(all.size(), false);
  for (int i : uniform_sample(all, static_cast<std::size_t>(std::max(count, 0)), seed))
    kept[static_cast<std::size_t>(i)] = true;
  return pairs_where(data, kept);
}

BcDataset first_pairs(const BcDataset& data, int count) {
  BcDataset out = empty_like(data);
  for (int i = 0; i < std::min(count, data.size()); ++i) copy_pair(data, i, out);
  return out;
}

}  // namespace sc
