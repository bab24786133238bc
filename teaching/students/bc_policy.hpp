#pragma once
// A behaviour-cloned policy: the paper's synthetic students (appendix) are 4-layer MLPs trained on
// goal-conditioned (state, action) pairs of the expert. Torch lives behind the pimpl (bc_policy_torch.cpp).
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace sc {

struct BcTrainingConfig {
  int epochs = 50;
  double learning_rate = 5e-4;  // paper appendix
  int batch_size = 256;         // paper appendix
  std::uint64_t seed = 0;
  // Called after every epoch with the epoch count so far and that epoch's mean loss (learning curves).
  std::function<void(int epoch, double loss)> after_epoch;
};

// Flat training pairs: states N x state_dim, actions N x action_dim (row-major).
struct BcDataset {
  int state_dim = 0;
  int action_dim = 0;
  std::vector<float> states;
  std::vector<float> actions;
  int size() const { return action_dim > 0 ? static_cast<int>(actions.size()) / action_dim : 0; }
  void append(const BcDataset& other);
};

class BcPolicy {
 public:
  // hidden: width of the three hidden layers (4 linear layers in total); actions are tanh-bounded to [-1,1].
  BcPolicy(int state_dim, int action_dim, int hidden, std::uint64_t init_seed);
  ~BcPolicy();
  BcPolicy(BcPolicy&&) noexcept;
  BcPolicy& operator=(BcPolicy&&) noexcept;
  BcPolicy clone() const;  // deep copy (fine-tuning experiments start from the same student)

  // Trains with Adam on mean squared error; returns the final epoch's mean training loss.
  double train(const BcDataset& data, const BcTrainingConfig& config);
  // Mean squared error on a dataset (no gradient).
  double evaluate(const BcDataset& data) const;
  // Deterministic action for one state.
  std::vector<float> act(const std::vector<float>& state) const;

  int state_dim() const;
  int action_dim() const;

 private:
  struct Impl;
  explicit BcPolicy(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace sc
