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

BcDataset keep_reverse_fraction(const BcDataset& data, double keep_fraction, std::uint64_t seed) {
  if (!(keep_fraction >= 0.0 && keep_fraction <= 1.0))
    throw InputError("reverse-action filter", "keep fraction must lie in [0, 1], got " + std::to_string(keep_fraction));
  std::vector<int> reverse;
  for (int i = 0; i < data.size(); ++i)
    if (is_reverse(data, i)) reverse.push_back(i);
  const auto keep = static_cast<std::size_t>(std::lround(keep_fraction * static_cast<double>(reverse.size())));
  // Partial Fisher-Yates with our RNG: the first `keep` entries are a uniform sample without replacement.
  Rng rng(seed);
  for (std::size_t i = 0; i < keep; ++i)
    std::swap(reverse[i], reverse[i + static_cast<std::size_t>(rng.below(reverse.size() - i))]);
  std::vector<bool> kept(static_cast<std::size_t>(data.size()), true);
  for (std::size_t i = keep; i < reverse.size(); ++i) kept[static_cast<std::size_t>(reverse[i])] = false;
  BcDataset out = empty_like(data);
  for (int i = 0; i < data.size(); ++i)
    if (kept[static_cast<std::size_t>(i)]) copy_pair(data, i, out);
  return out;
}

BcDataset first_pairs(const BcDataset& data, int count) {
  BcDataset out = empty_like(data);
  for (int i = 0; i < std::min(count, data.size()); ++i) copy_pair(data, i, out);
  return out;
}

}  // namespace sc
