// The hand-written BPTT of packed_lstm against plain autograd on a per-step LSTM.
#include <gtest/gtest.h>

#include "teaching/skills/compile_torch.hpp"
#include "teaching/skills/synthetic_sequences.hpp"

namespace sc::compile_detail {
namespace {

TEST(PackedLstm, ForwardAndGradientsMatchPlainAutograd) {
  torch::manual_seed(3);
  const std::int64_t hid = 3;
  const std::vector<std::int64_t> lengths{5, 3, 3, 1};
  const Packing packing = Packing::from_lengths(lengths);
  const std::int64_t rows = 4, n = packing.total();
  ASSERT_EQ(n, 12);
  auto opt = torch::TensorOptions().dtype(torch::kFloat32).requires_grad(true);
  torch::Tensor xproj = torch::randn({n, 4 * hid}, opt);
  torch::Tensor h0 = torch::randn({rows, hid}, opt), c0 = torch::randn({rows, hid}, opt);
  torch::Tensor w = torch::randn({4 * hid, hid}, opt);
  torch::Tensor mask = torch::rand({n}, opt);
  const torch::Tensor probe = torch::randn({n, hid});

  const torch::Tensor out = packed_lstm(xproj, h0, c0, w, mask, packing);
  (out * probe).sum().backward();
  const std::vector<torch::Tensor> fast{out.detach(),      xproj.grad().clone(), h0.grad().clone(),
                                        c0.grad().clone(), w.grad().clone(),     mask.grad().clone()};
  for (auto* t : {&xproj, &h0, &c0, &w, &mask}) t->mutable_grad() = torch::Tensor();

  std::vector<torch::Tensor> outs(static_cast<std::size_t>(n));
  for (std::int64_t r = 0; r < rows; ++r) {
    torch::Tensor h = h0[r], c = c0[r];
    for (std::int64_t t = 0; t < lengths[static_cast<std::size_t>(r)]; ++t) {
      const std::int64_t idx = packing.offset[static_cast<std::size_t>(t)] + r;
      const torch::Tensor g = xproj[idx] + torch::mv(w, h);
      const torch::Tensor i = torch::sigmoid(g.narrow(0, 0, hid)), f = torch::sigmoid(g.narrow(0, hid, hid));
      const torch::Tensor o = torch::sigmoid(g.narrow(0, 2 * hid, hid)), gg = torch::tanh(g.narrow(0, 3 * hid, hid));
      c = f * c + i * gg;
      h = o * torch::tanh(c);
      h = h * mask[idx];
      c = c * mask[idx];
      outs[static_cast<std::size_t>(idx)] = h;
    }
  }
  const torch::Tensor slow = torch::stack(outs);
  (slow * probe).sum().backward();
  const std::vector<torch::Tensor> reference{slow.detach(), xproj.grad(), h0.grad(), c0.grad(), w.grad(), mask.grad()};
  const char* names[] = {"output", "d xproj", "d h0", "d c0", "d w_hh", "d mask"};
  for (std::size_t k = 0; k < fast.size(); ++k)
    EXPECT_TRUE(torch::allclose(fast[k], reference[k], 1e-4, 1e-5)) << names[k] << "\n"
                                                                    << fast[k] << "\n"
                                                                    << reference[k];
}

// hard_readout (each pass from its hard start, raw-row steps) must give exactly the boundaries and skills of
// the training-time encoder in eval mode, on untrained networks whose boundaries fall anywhere (also before
// an earlier boundary), in the writing (action) and parking (statediff+action) modes.
void expect_same_readout(CompileConfig config, const std::vector<PlantedSequence>& planted, std::uint64_t seed,
                         double weight_scale) {
  std::vector<StepSequence> raw;
  for (const auto& p : planted) raw.push_back(p.steps);
  if (config.uses_states()) config.state_dim = raw.front().state_dim;
  auto gen = at::detail::createCPUGenerator(seed);
  CompileNetwork net(config, gen);
  {
    torch::NoGradGuard no_grad;
    for (auto& [name, t] : net.named()) t->mul_(weight_scale);  // larger weights: more varied boundaries
  }
  const auto inputs = to_model_inputs(raw, config, "trajectory");
  std::vector<const StepSequence*> steps;
  for (const auto& m : inputs) steps.push_back(&m.steps);
  const Batch batch = make_batch(steps, config);
  torch::NoGradGuard no_grad;
  const HardReadout fast = hard_readout(net, batch), reference = hard_readout_reference(net, batch);
  EXPECT_EQ(fast.boundaries, reference.boundaries) << "seed " << seed << " scale " << weight_scale;
  EXPECT_EQ(fast.skills, reference.skills) << "seed " << seed << " scale " << weight_scale;
}

TEST(CompileInference, FastReadoutMatchesTheTrainingEncoderExactly) {
  for (std::uint64_t seed : {1u, 2u, 3u})
    for (double scale : {1.0, 3.0}) {
      expect_same_readout(CompileConfig::writing_defaults(), writing_like_sequences(5, 8, seed), seed, scale);
      expect_same_readout(CompileConfig::parking_defaults(), parking_like_sequences(20, 11, 29, seed), seed, scale);
    }
}

}  // namespace
}  // namespace sc::compile_detail
