// The relaxed latent sample of compile_forward_torch.cpp: soft as in the paper, or straight-through.
#include <gtest/gtest.h>

#include "teaching/skills/compile_torch.hpp"

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

}  // namespace
}  // namespace sc::compile_detail
