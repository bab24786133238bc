#include <torch/torch.h>

#include <algorithm>
#include <numeric>

#include "engine/core/rng.hpp"
#include "teaching/students/bc_policy.hpp"

namespace sc {

void BcDataset::append(const BcDataset& other) {
  if (other.size() == 0) return;
  if (size() == 0) {
    state_dim = other.state_dim;
    action_dim = other.action_dim;
  }
  states.insert(states.end(), other.states.begin(), other.states.end());
  actions.insert(actions.end(), other.actions.begin(), other.actions.end());
}

namespace {

torch::nn::Sequential make_mlp(int in, int out, int hidden) {
  return torch::nn::Sequential(torch::nn::Linear(in, hidden), torch::nn::ReLU(), torch::nn::Linear(hidden, hidden),
                               torch::nn::ReLU(), torch::nn::Linear(hidden, hidden), torch::nn::ReLU(),
                               torch::nn::Linear(hidden, out), torch::nn::Tanh());
}

torch::Tensor as_tensor(const std::vector<float>& data, int rows, int cols) {
  return torch::from_blob(const_cast<float*>(data.data()), {rows, cols}, torch::kFloat32).clone();
}

}  // namespace

struct BcPolicy::Impl {
  int state_dim;
  int action_dim;
  int hidden;
  torch::nn::Sequential net{nullptr};
};

BcPolicy::BcPolicy(int state_dim, int action_dim, int hidden, std::uint64_t init_seed)
    : impl_(std::make_unique<Impl>()) {
  torch::manual_seed(init_seed);
  impl_->state_dim = state_dim;
  impl_->action_dim = action_dim;
  impl_->hidden = hidden;
  impl_->net = make_mlp(state_dim, action_dim, hidden);
}

BcPolicy::BcPolicy(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BcPolicy::~BcPolicy() = default;
BcPolicy::BcPolicy(BcPolicy&&) noexcept = default;
BcPolicy& BcPolicy::operator=(BcPolicy&&) noexcept = default;

BcPolicy BcPolicy::clone() const {
  auto copy = std::make_unique<Impl>(*impl_);
  copy->net = std::dynamic_pointer_cast<torch::nn::SequentialImpl>(impl_->net->clone());
  return BcPolicy(std::move(copy));
}

int BcPolicy::state_dim() const { return impl_->state_dim; }
int BcPolicy::action_dim() const { return impl_->action_dim; }

double BcPolicy::train(const BcDataset& data, const BcTrainingConfig& config) {
  const int n = data.size();
  if (n == 0 || config.epochs <= 0) return 0.0;
  torch::manual_seed(config.seed);
  auto states = as_tensor(data.states, n, data.state_dim);
  auto actions = as_tensor(data.actions, n, data.action_dim);
  torch::optim::Adam optimizer(impl_->net->parameters(), torch::optim::AdamOptions(config.learning_rate));
  impl_->net->train();
  Rng rng(config.seed);
  std::vector<std::int64_t> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  double epoch_loss = 0.0;
  for (int epoch = 0; epoch < config.epochs; ++epoch) {
    // Fisher-Yates with our RNG so the batches do not depend on the standard library.
    for (int i = n - 1; i > 0; --i) std::swap(order[i], order[rng.below(static_cast<std::uint64_t>(i) + 1)]);
    auto index = torch::from_blob(order.data(), {n}, torch::kInt64);
    double total = 0.0;
    for (int start = 0; start < n; start += config.batch_size) {
      const int count = std::min(config.batch_size, n - start);
      auto batch = index.narrow(0, start, count);
      auto loss = torch::mse_loss(impl_->net->forward(states.index_select(0, batch)), actions.index_select(0, batch));
      optimizer.zero_grad();
      loss.backward();
      optimizer.step();
      total += loss.item<double>() * count;
    }
    epoch_loss = total / n;
    if (config.after_epoch) {
      impl_->net->eval();
      config.after_epoch(epoch + 1, epoch_loss);
      impl_->net->train();
    }
  }
  impl_->net->eval();
  return epoch_loss;
}

double BcPolicy::evaluate(const BcDataset& data) const {
  const int n = data.size();
  if (n == 0) return 0.0;
  torch::NoGradGuard no_grad;
  auto prediction = impl_->net->forward(as_tensor(data.states, n, data.state_dim));
  return torch::mse_loss(prediction, as_tensor(data.actions, n, data.action_dim)).item<double>();
}

std::vector<float> BcPolicy::act(const std::vector<float>& state) const {
  torch::NoGradGuard no_grad;
  auto out = impl_->net->forward(as_tensor(state, 1, impl_->state_dim)).contiguous();
  const float* p = out.data_ptr<float>();
  return std::vector<float>(p, p + impl_->action_dim);
}

}  // namespace sc
