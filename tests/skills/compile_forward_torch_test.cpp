// The relaxed latent sample of compile_forward_torch.cpp: soft as in the paper, or straight-through.
#include <gtest/gtest.h>

#include "teaching/skills/compile_torch.hpp"
#include "teaching/skills/synthetic_sequences.hpp"

namespace sc::compile_detail {
namespace {

torch::Tensor some_logits() {
  return torch::tensor({{0.3f, -1.2f, 0.9f, 0.0f}, {2.0f, 1.5f, -0.5f, 0.1f}, {0.0f, 0.0f, 0.0f, 0.0f}});
}

// d(sum(w * sample))/d(logits) for a fixed weighting w, with the generator at `seed`.
torch::Tensor gradient_of_sample(bool straight_through, std::uint64_t seed, torch::Tensor* sample) {
  auto gen = at::detail::createCPUGenerator(seed);
  const torch::Tensor logits = some_logits().requires_grad_(true);
  *sample = relaxed_latent(logits, &gen, straight_through);
  const torch::Tensor w = torch::tensor({1.0f, -2.0f, 0.5f, 3.0f});
  (*sample * w).sum().backward();
  return logits.grad();
}

TEST(RelaxedLatent, StraightThroughIsTheSoftSamplesArgmaxForwardAndItsGradientBackward) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    torch::Tensor soft, hard;
    const torch::Tensor soft_grad = gradient_of_sample(false, seed, &soft);
    const torch::Tensor hard_grad = gradient_of_sample(true, seed, &hard);
    const torch::Tensor one_hot = torch::one_hot(soft.argmax(-1), soft.size(-1)).to(torch::kFloat32);
    EXPECT_TRUE(torch::allclose(hard.detach(), one_hot, 0.0, 1e-6)) << "seed " << seed << "\n" << hard << "\n" << soft;
    EXPECT_FALSE(torch::equal(soft.detach(), one_hot)) << "seed " << seed << ": the relaxed sample is not one-hot";
    EXPECT_TRUE(torch::allclose(hard_grad, soft_grad, 1e-6, 1e-7)) << "seed " << seed;
    EXPECT_GT(hard_grad.abs().sum().item<double>(), 0.0) << "seed " << seed;
  }
}

// The loss terms of one batch of writing-like words with untrained weights (generator at `seed`).
LossTerms losses_with_usage_weight(double beta_usage, std::uint64_t seed) {
  CompileConfig config = CompileConfig::writing_defaults();
  config.beta_usage = beta_usage;
  std::vector<StepSequence> raw;
  for (const auto& p : writing_like_sequences(4, 8, 5)) raw.push_back(p.steps);
  auto gen = at::detail::createCPUGenerator(seed);
  const CompileNetwork net(config, gen);
  const auto inputs = to_model_inputs(raw, config, "trajectory");
  std::vector<const StepSequence*> steps;
  for (const auto& m : inputs) steps.push_back(&m.steps);
  auto sample = at::detail::createCPUGenerator(seed + 100);
  return compute_losses(net, make_batch(steps, config), true, &sample);
}

TEST(CompileLosses, TheUsageBonusSubtractsTheEntropyOfTheMeanPosterior) {
  const LossTerms plain = losses_with_usage_weight(0.0, 7), bonus = losses_with_usage_weight(2.5, 7);
  const double entropy = bonus.usage_entropy.item<double>();
  EXPECT_GT(entropy, 0.0);
  EXPECT_LE(entropy, std::log(static_cast<double>(CompileConfig::writing_defaults().latent_size)) + 1e-9);
  EXPECT_DOUBLE_EQ(plain.usage_entropy.item<double>(), entropy);
  EXPECT_NEAR(bonus.total.item<double>(), plain.total.item<double>() - 2.5 * entropy, 1e-3);
}

}  // namespace
}  // namespace sc::compile_detail
