// CompILE parameters and batches (see compile_torch.hpp).
#include <algorithm>
#include <cmath>
#include <numeric>

#include "engine/core/error.hpp"
#include "teaching/skills/compile_torch.hpp"

namespace sc::compile_detail {

namespace {

torch::Tensor uniform(std::vector<std::int64_t> shape, double bound, at::Generator& gen) {
  auto t = torch::rand(shape, gen, torch::kFloat32).mul_(2.0 * bound).sub_(bound);
  return t.set_requires_grad(true);
}

Linear make_linear(std::int64_t in, std::int64_t out, at::Generator& gen) {
  const double bound = 1.0 / std::sqrt(static_cast<double>(in));
  Linear l;
  l.weight = uniform({out, in}, bound, gen);
  l.bias = uniform({out}, bound, gen);
  return l;
}

Mlp make_mlp(std::int64_t in, std::int64_t mid, std::int64_t out, at::Generator& gen) {
  Mlp m;
  m.first = make_linear(in, mid, gen);
  m.second = make_linear(mid, out, gen);
  return m;
}

// LSTM input weights plus the sum of PyTorch's two bias vectors (each U(+-1/sqrt(H))).
Linear make_lstm_input(std::int64_t in, std::int64_t hid, at::Generator& gen) {
  const double bound = 1.0 / std::sqrt(static_cast<double>(hid));
  Linear l;
  l.weight = uniform({4 * hid, in}, bound, gen);
  auto b_ih = torch::rand({4 * hid}, gen, torch::kFloat32).mul_(2.0 * bound).sub_(bound);
  auto b_hh = torch::rand({4 * hid}, gen, torch::kFloat32).mul_(2.0 * bound).sub_(bound);
  l.bias = (b_ih + b_hh).set_requires_grad(true);
  return l;
}

}  // namespace

CompileNetwork::CompileNetwork(const CompileConfig& c, at::Generator& gen) : config(c) {
  const std::int64_t h = c.hidden, a = c.action_dim, s = c.state_dim, m = c.latent_size;
  const bool st = c.uses_states();
  // Embedding width: H for actions alone, H/2 each when states are embedded too (reference §3.3).
  const std::int64_t emb = st ? h / 2 : h;
  if (st) enc_state = make_mlp(s, emb, emb, gen);
  enc_action = make_mlp(a, emb, emb, gen);
  enc_ih = make_lstm_input(h, h, gen);
  enc_hh = uniform({4 * h, h}, 1.0 / std::sqrt(static_cast<double>(h)), gen);
  head_b = make_mlp(h, h, 1, gen);
  head_z = make_mlp(h, h, m, gen);
  dec_1 = make_linear(m, h, gen);
  dec_1a = make_linear(h, h, gen);
  dec_1b = make_linear(h, h, gen);
  if (st) dec_state = make_mlp(s, emb, emb, gen);
  dec_action = make_mlp(a, emb, emb, gen);
  dec_ih = make_lstm_input(h, h, gen);
  dec_hh = uniform({4 * h, h}, 1.0 / std::sqrt(static_cast<double>(h)), gen);
  head_action = make_mlp(h, h, a, gen);
  if (st) head_state = make_mlp(h, h, s, gen);
}

std::vector<std::pair<std::string, torch::Tensor*>> CompileNetwork::named() {
  std::vector<std::pair<std::string, torch::Tensor*>> out;
  auto lin = [&](const std::string& name, Linear& l) {
    if (!l.weight.defined()) return;
    out.emplace_back(name + ".weight", &l.weight);
    out.emplace_back(name + ".bias", &l.bias);
  };
  auto mlp = [&](const std::string& name, Mlp& m) {
    lin(name + ".0", m.first);
    lin(name + ".2", m.second);
  };
  mlp("encoder_embed_state", enc_state);
  mlp("encoder_embed_action", enc_action);
  lin("encoder_lstm.input", enc_ih);
  out.emplace_back("encoder_lstm.weight_hh", &enc_hh);
  mlp("head_b", head_b);
  mlp("head_z", head_z);
  lin("decoder_1", dec_1);
  lin("decoder_1a", dec_1a);
  lin("decoder_1b", dec_1b);
  mlp("decoder_embed_state", dec_state);
  mlp("decoder_embed_action", dec_action);
  lin("decoder_lstm.input", dec_ih);
  out.emplace_back("decoder_lstm.weight_hh", &dec_hh);
  mlp("decoder_head_action", head_action);
  mlp("decoder_head_state", head_state);
  return out;
}

std::vector<torch::Tensor> CompileNetwork::parameters() {
  std::vector<torch::Tensor> out;
  for (auto& [name, t] : named()) out.push_back(*t);
  return out;
}

torch::Tensor encoder_actions(const CompileNetwork& net, const Batch& batch) {
  return net.config.encoder_reads_actions ? batch.actions : torch::zeros_like(batch.actions);
}

Batch make_batch(const std::vector<const StepSequence*>& steps, const CompileConfig& config,
                 const std::vector<const std::vector<int>*>& fixed_boundaries) {
  Batch batch;
  batch.size = static_cast<std::int64_t>(steps.size());
  batch.source.resize(steps.size());
  std::iota(batch.source.begin(), batch.source.end(), std::size_t{0});
  std::stable_sort(batch.source.begin(), batch.source.end(),
                   [&](std::size_t a, std::size_t b) { return steps[a]->length() > steps[b]->length(); });
  for (auto i : batch.source) batch.lengths.push_back(steps[i]->length());
  batch.steps = batch.lengths.empty() ? 0 : batch.lengths.front();
  const std::int64_t positions = batch.steps + 1, b_size = batch.size;
  const std::int64_t a_dim = config.action_dim, s_dim = config.uses_states() ? config.state_dim : 0;

  batch.actions = torch::zeros({positions, b_size, a_dim});
  if (s_dim > 0) batch.states = torch::zeros({positions, b_size, s_dim});
  float* ap = batch.actions.data_ptr<float>();
  float* sp = s_dim > 0 ? batch.states.data_ptr<float>() : nullptr;
  for (std::int64_t b = 0; b < b_size; ++b) {
    const StepSequence& seq = *steps[batch.source[static_cast<std::size_t>(b)]];
    for (std::int64_t t = 0; t < batch.lengths[static_cast<std::size_t>(b)]; ++t) {
      for (std::int64_t d = 0; d < a_dim; ++d)
        ap[(t * b_size + b) * a_dim + d] = seq.actions[static_cast<std::size_t>(t * a_dim + d)];
      for (std::int64_t d = 0; d < s_dim; ++d)
        sp[(t * b_size + b) * s_dim + d] = seq.states[static_cast<std::size_t>(t * s_dim + d)];
    }
  }

  // Row b runs encoder steps 0..T_b: step T_b reads padding and scores a boundary at the very end.
  std::vector<std::int64_t> runs;
  for (auto len : batch.lengths) runs.push_back(len + 1);
  batch.encoder = Packing::from_lengths(runs);
  const std::int64_t n_total = batch.encoder.total();
  std::vector<std::int64_t> pack(static_cast<std::size_t>(n_total));
  std::vector<std::int64_t> unpack(static_cast<std::size_t>(positions * b_size), n_total);
  for (std::size_t t = 0; t < batch.encoder.active.size(); ++t)
    for (std::int64_t r = 0; r < batch.encoder.active[t]; ++r) {
      const std::int64_t packed = batch.encoder.offset[t] + r;
      const std::int64_t padded = static_cast<std::int64_t>(t) * b_size + r;
      pack[static_cast<std::size_t>(packed)] = padded;
      unpack[static_cast<std::size_t>(padded)] = packed;
    }
  batch.pack_index = torch::tensor(pack, torch::kInt64);
  batch.unpack_index = torch::tensor(unpack, torch::kInt64);
  if (!fixed_boundaries.empty())
    for (auto i : batch.source) batch.fixed_boundaries.push_back(*fixed_boundaries[i]);
  return batch;
}

}  // namespace sc::compile_detail
