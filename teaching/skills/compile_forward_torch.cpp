// CompILE forward pass and losses (reference-facts §3.4-3.5), with the reference's bugs fixed:
//  * boundary positions run 1..T_b inclusive (T_b = true length) and the last segment ends at T_b, so the
//    final action is reconstructed (reference: the last segment stopped at T_b - 1, bug §6.8); every
//    trajectory gets one zero-padded encoder step so the boundary at T_b is scored from the same kind of
//    input for every length (the reference allowed it only when the batch happened to be padded);
//  * the boundary KL covers every segment that has a boundary (reference: segment 0 only, times K), with
//    a Poisson prior on the segment's own length t - start (reference: position t paired with value t+1,
//    absolute positions, bug §6.9), normalised over the trajectory's true length, not the padded batch;
//  * each segment is decoded from its own start (the hard start implied by the sampled earlier boundaries)
//    instead of absolute t = 0 (bug §6.7: the decoder had to learn *when* its segment happens). This also
//    lets the decoder run only over (about) its own segment (packed rows, see decode()), which is most of
//    the speed-up. Before its start a segment's weight is ~0; it reuses its first output there.
#include <algorithm>
#include <cmath>

#include "teaching/skills/compile_torch.hpp"

namespace sc::compile_detail {

namespace {

using torch::Tensor;
namespace F = torch::nn::functional;
constexpr double kNegInf = -1e30;  // as the reference: finite, so softmax gradients stay NaN-free
constexpr double kEps = 1e-17;

Tensor gumbel_like(const Tensor& t, at::Generator* gen) {
  Tensor u = torch::rand(t.sizes(), *gen, t.options());
  return -torch::log(kEps - torch::log(u + kEps));
}

Tensor one_hot_argmax(const Tensor& logits) {
  return F::one_hot(logits.argmax(-1), logits.size(-1)).to(logits.scalar_type());
}

// [B, P] additive mask: 0 where a boundary may fall (1..T_b), -1e30 elsewhere (t = 0 and padding).
Tensor boundary_position_mask(const Batch& batch) {
  const std::int64_t positions = batch.steps + 1;
  Tensor m = torch::full({batch.size, positions}, kNegInf);
  auto acc = m.accessor<float, 2>();
  for (std::int64_t b = 0; b < batch.size; ++b)
    for (std::int64_t t = 1; t <= batch.lengths[static_cast<std::size_t>(b)]; ++t) acc[b][t] = 0.0f;
  return m;
}

// One-hot [B, P] of boundary k where the caller fixed it (diagnostic: the segmentation is given, so only
// the latent heads and the decoder learn; the boundary logits are still computed for the KL term).
Tensor fixed_boundary(const Batch& batch, int k, std::int64_t positions) {
  std::vector<std::int64_t> at;
  for (const auto& row : batch.fixed_boundaries) at.push_back(row[static_cast<std::size_t>(k)]);
  return F::one_hot(torch::tensor(at, torch::kInt64), positions).to(torch::kFloat32);
}

// Everything the K sequential encoder passes produce.
struct Encoded {
  std::vector<Tensor> boundary_logits;     // k < K-1: [B, P] masked logits
  std::vector<Tensor> latent_logits;       // [B, M]
  std::vector<Tensor> latents;             // [B, M] samples (relaxed) or one-hot
  std::vector<Tensor> weights;             // [B, T] soft share of each action in segment k
  std::vector<std::vector<int>> position;  // [B][K] hard boundary (argmax of the sample)
  std::vector<std::vector<int>> start;     // [B][K] hard start: max of earlier hard boundaries
};

Encoded encode(const CompileNetwork& net, const Batch& batch, bool relaxed, at::Generator* gen, bool weights) {
  const auto& cfg = net.config;
  const std::int64_t b_size = batch.size, t_max = batch.steps, positions = t_max + 1, hid = cfg.hidden;
  const int k_count = cfg.num_segments;
  Tensor x = net.enc_action(encoder_actions(net, batch));
  if (cfg.uses_states()) x = torch::cat({net.enc_state(batch.states), x}, -1);  // state first (§3.3)
  const Tensor xproj = net.enc_ih(x.view({positions * b_size, hid}).index_select(0, batch.pack_index));
  const Tensor pos_mask = boundary_position_mask(batch);
  const Tensor zero_row = torch::zeros({1, hid});
  const Tensor zero_one = torch::zeros({1});

  Encoded out;
  out.position.assign(static_cast<std::size_t>(b_size), std::vector<int>(static_cast<std::size_t>(k_count)));
  out.start = out.position;
  Tensor mask_prev;  // [B, P] product of the earlier boundaries' CDFs (undefined = all ones)
  for (int k = 0; k < k_count; ++k) {
    Tensor mask_packed;
    if (mask_prev.defined()) mask_packed = mask_prev.t().reshape({-1}).index_select(0, batch.pack_index);
    const Tensor e = packed_lstm(xproj, Tensor(), Tensor(), net.enc_hh, mask_packed, batch.encoder);
    Tensor b;
    if (k < k_count - 1) {
      Tensor logits = torch::cat({net.head_b(e).squeeze(-1), zero_one}).index_select(0, batch.unpack_index);
      logits = logits.view({positions, b_size}).t() + pos_mask;
      out.boundary_logits.push_back(logits);
      b = relaxed ? torch::softmax(logits + gumbel_like(logits, gen), -1) : one_hot_argmax(logits);
      if (!batch.fixed_boundaries.empty()) b = fixed_boundary(batch, k, positions);
    } else {
      std::vector<std::int64_t> ends(batch.lengths.begin(), batch.lengths.end());
      b = F::one_hot(torch::tensor(ends, torch::kInt64), positions).to(torch::kFloat32);
    }
    // Readout: the encoding one step before the boundary (the segment's last action), §3.4 step 3.
    const Tensor e_pad = torch::cat({e, zero_row}).index_select(0, batch.unpack_index).view({positions, b_size, hid});
    const Tensor readout = torch::einsum("tbh,bt->bh", {e_pad.narrow(0, 0, t_max), b.narrow(1, 1, t_max)});
    const Tensor z_logits = net.head_z(readout);
    out.latent_logits.push_back(z_logits);
    out.latents.push_back(relaxed ? relaxed_latent(z_logits, gen, cfg.straight_through_latents)
                                  : one_hot_argmax(z_logits));

    const Tensor hard = b.argmax(-1).contiguous();
    const auto* hp = hard.data_ptr<std::int64_t>();
    for (std::int64_t r = 0; r < b_size; ++r) {
      auto& pos = out.position[static_cast<std::size_t>(r)];
      pos[static_cast<std::size_t>(k)] = static_cast<int>(hp[r]);
      out.start[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] =
          k == 0 ? 0
                 : std::max(out.start[static_cast<std::size_t>(r)][static_cast<std::size_t>(k - 1)],
                            pos[static_cast<std::size_t>(k - 1)]);
    }
    if (!weights && k == k_count - 1) break;
    const Tensor cdf = torch::cumsum(b, 1);
    if (weights) {
      Tensor w = 1.0 - cdf.narrow(1, 0, t_max);
      if (mask_prev.defined()) w = w * mask_prev.narrow(1, 0, t_max);
      out.weights.push_back(w);
    }
    mask_prev = mask_prev.defined() ? mask_prev * cdf : cdf;
  }
  return out;
}

struct Decoded {
  Tensor actions;  // [B, K, T, A] reconstruction aligned to absolute time
  Tensor states;   // [B, K, T, S] (state modes)
};

Tensor embed_decoder_input(const CompileNetwork& net, const Tensor& prev_action, const Tensor& prev_state) {
  Tensor x = net.dec_action(prev_action);
  if (net.config.uses_states()) x = torch::cat({x, net.dec_state(prev_state)}, -1);  // action first (§3.3)
  return x;
}

// Open-loop decoding of every (trajectory, segment) row from its own start to the trajectory's end.
Decoded decode(const CompileNetwork& net, const Batch& batch, const Encoded& enc) {
  const auto& cfg = net.config;
  const std::int64_t b_size = batch.size, t_max = batch.steps, hid = cfg.hidden;
  const std::int64_t k_count = cfg.num_segments, rows = b_size * k_count;
  const std::int64_t a_dim = cfg.action_dim, s_dim = cfg.uses_states() ? cfg.state_dim : 1;

  // Each row runs from its segment's start to the sampled end plus a margin of half the segment (>= 3
  // steps), capped at the trajectory's end. Further out the relaxed weight of the segment is small once
  // boundaries sharpen, and the row's last output is reused there (gather clamps). This keeps decoder work
  // near B x T instead of B x K x T (the reference decoded every segment over the whole padded batch).
  std::vector<std::int64_t> need(static_cast<std::size_t>(rows));
  for (std::int64_t b = 0; b < b_size; ++b)
    for (std::int64_t k = 0; k < k_count; ++k) {
      const std::int64_t len = batch.lengths[static_cast<std::size_t>(b)];
      const std::int64_t s = enc.start[static_cast<std::size_t>(b)][static_cast<std::size_t>(k)];
      const std::int64_t e =
          std::max<std::int64_t>(s, enc.position[static_cast<std::size_t>(b)][static_cast<std::size_t>(k)]);
      const std::int64_t reach = std::min(len, e + std::max<std::int64_t>(3, (e - s) / 2));
      need[static_cast<std::size_t>(b * k_count + k)] = std::max<std::int64_t>(1, reach - s);
    }
  std::vector<std::int64_t> order(static_cast<std::size_t>(rows));
  for (std::int64_t r = 0; r < rows; ++r) order[static_cast<std::size_t>(r)] = r;
  std::stable_sort(order.begin(), order.end(), [&](std::int64_t a, std::int64_t b) {
    return need[static_cast<std::size_t>(a)] > need[static_cast<std::size_t>(b)];
  });
  std::vector<std::int64_t> rank(static_cast<std::size_t>(rows)), sorted_need;
  for (std::int64_t i = 0; i < rows; ++i) {
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;
    sorted_need.push_back(need[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])]);
  }
  const Packing packing = Packing::from_lengths(sorted_need);
  const std::int64_t n_total = packing.total();

  const Tensor z = torch::stack(enc.latents, 1).view({rows, cfg.latent_size}).index_select(0, torch::tensor(order));
  const Tensor h0 = net.dec_1a(torch::relu(net.dec_1(z)));
  const Tensor c0 = net.dec_1b(h0);

  // Pass 1 (no autograd): run the decoder step by step to learn what each step feeds back (the reference
  // feeds the decoder its own previous outputs with the gradient stopped, so they are constants for
  // autograd). Pass 2 then attaches ONE packed-LSTM graph node that replays these very steps.
  Tensor fb_action = torch::zeros({n_total, a_dim}), fb_state = torch::zeros({n_total, s_dim});
  compile_detail::PackedLstmRun run(packing, hid, fb_action.options());
  {
    torch::NoGradGuard no_grad;
    const Tensor h_init = h0.detach().contiguous(), c_init = c0.detach().contiguous();
    run_decoder_feedback(net, packing, h_init, c_init, fb_action, fb_state, run);
  }
  const Tensor xd = embed_decoder_input(net, fb_action, fb_state);
  const Tensor hd = packed_lstm(net.dec_ih(xd), h0, c0, net.dec_hh, Tensor(), packing, &run);

  std::vector<std::int64_t> gather(static_cast<std::size_t>(rows * t_max));
  for (std::int64_t b = 0; b < b_size; ++b)
    for (std::int64_t k = 0; k < k_count; ++k) {
      const std::int64_t r = b * k_count + k;
      const std::int64_t s = enc.start[static_cast<std::size_t>(b)][static_cast<std::size_t>(k)];
      for (std::int64_t t = 0; t < t_max; ++t) {
        const std::int64_t j = std::clamp<std::int64_t>(t - s, 0, need[static_cast<std::size_t>(r)] - 1);
        gather[static_cast<std::size_t>(r * t_max + t)] =
            packing.offset[static_cast<std::size_t>(j)] + rank[static_cast<std::size_t>(r)];
      }
    }
  const Tensor index = torch::tensor(gather, torch::kInt64);
  Decoded out;
  out.actions = torch::tanh(net.head_action(hd)).index_select(0, index).view({b_size, k_count, t_max, a_dim});
  if (cfg.uses_states())
    out.states = net.head_state(hd).index_select(0, index).view({b_size, k_count, t_max, cfg.state_dim});
  return out;
}

// log pi(t) for boundary positions t = 1..T_b of a segment starting at `start`: Poisson on the segment's
// length max(t - start, 0), normalised over the valid positions only. Returns [K-1, B, P].
Tensor log_length_prior(const Batch& batch, const Encoded& enc, double rate, int k_count) {
  const std::int64_t positions = batch.steps + 1;
  std::vector<double> log_pmf(static_cast<std::size_t>(positions));
  for (std::int64_t n = 0; n < positions; ++n)
    log_pmf[static_cast<std::size_t>(n)] =
        static_cast<double>(n) * std::log(rate) - rate - std::lgamma(static_cast<double>(n) + 1.0);
  Tensor prior = torch::zeros({std::max(k_count - 1, 0), batch.size, positions});
  auto acc = prior.accessor<float, 3>();
  for (int k = 0; k + 1 < k_count; ++k)
    for (std::int64_t b = 0; b < batch.size; ++b) {
      const std::int64_t len = batch.lengths[static_cast<std::size_t>(b)];
      const int s = enc.start[static_cast<std::size_t>(b)][static_cast<std::size_t>(k)];
      double peak = -1e300;
      for (std::int64_t t = 1; t <= len; ++t)
        peak = std::max(peak, log_pmf[static_cast<std::size_t>(std::max<std::int64_t>(t - s, 0))]);
      double sum = 0.0;
      for (std::int64_t t = 1; t <= len; ++t)
        sum += std::exp(log_pmf[static_cast<std::size_t>(std::max<std::int64_t>(t - s, 0))] - peak);
      const double norm = peak + std::log(sum);
      for (std::int64_t t = 1; t <= len; ++t)
        acc[k][b][t] = static_cast<float>(log_pmf[static_cast<std::size_t>(std::max<std::int64_t>(t - s, 0))] - norm);
    }
  return prior;
}

// Sum over the batch's labelled segments of -log q(z = unit) (Batch::segment_units; 0 without labels).
Tensor unit_cross_entropy(const Batch& batch, const std::vector<Tensor>& latent_logits) {
  if (batch.segment_units.empty()) return torch::zeros({});
  std::vector<std::int64_t> target;
  for (std::size_t k = 0; k < latent_logits.size(); ++k)
    for (const auto& row : batch.segment_units) target.push_back(row[k]);
  const Tensor log_q = torch::log_softmax(torch::cat(latent_logits, 0), -1);  // [K * B, M], k-major
  return F::nll_loss(log_q, torch::tensor(target, torch::kInt64),
                     F::NLLLossFuncOptions().ignore_index(-1).reduction(torch::kSum));
}

}  // namespace

Tensor relaxed_latent(const Tensor& logits, at::Generator* gen, bool straight_through) {
  const Tensor soft = torch::softmax(logits + gumbel_like(logits, gen), -1);
  if (!straight_through) return soft;
  return one_hot_argmax(soft.detach()) + soft - soft.detach();
}

LossTerms compute_losses(const CompileNetwork& net, const Batch& batch, bool relaxed, at::Generator* gen) {
  const auto& cfg = net.config;
  const std::int64_t b_size = batch.size, t_max = batch.steps;
  const double inv_b = 1.0 / static_cast<double>(b_size);
  const Encoded enc = encode(net, batch, relaxed, gen, true);
  const Decoded dec = decode(net, batch, enc);
  const Tensor weights = torch::stack(enc.weights, 1);  // [B, K, T]

  LossTerms out;
  const Tensor actions = batch.actions.narrow(0, 0, t_max).transpose(0, 1).unsqueeze(1);  // [B, 1, T, A]
  out.nll_action = ((dec.actions - actions).pow(2).sum(-1) * weights).sum() * inv_b;
  out.nll_state = torch::zeros({});
  if (cfg.uses_states()) {
    const Tensor states = batch.states.narrow(0, 0, t_max).transpose(0, 1).unsqueeze(1);  // [B, 1, T, S]
    if (cfg.mode == CompileMode::StateAction) {
      out.nll_state = ((dec.states - states).pow(2).sum(-1) * weights).sum() * inv_b;
    } else if (t_max > 1) {
      // statediff: D_t = s_{t+1} - s_t against the decoded differences, weighted by P_k(t+1) (§3.5).
      const Tensor target = states.narrow(2, 1, t_max - 1) - states.narrow(2, 0, t_max - 1);
      const Tensor decoded = dec.states.narrow(2, 1, t_max - 1) - dec.states.narrow(2, 0, t_max - 1);
      out.nll_state = ((decoded - target).pow(2).sum(-1) * weights.narrow(2, 1, t_max - 1)).sum() * inv_b;
    }
  }
  const Tensor q = torch::softmax(torch::stack(enc.latent_logits, 1), -1);  // [B, K, M]
  out.kl_z = (q * torch::log(q + kEps)).sum() * inv_b;
  out.kl_b = torch::zeros({});
  if (cfg.num_segments > 1) {
    const Tensor log_prior = log_length_prior(batch, enc, cfg.prior_rate, cfg.num_segments);
    const Tensor p = torch::softmax(torch::stack(enc.boundary_logits, 0), -1);  // [K-1, B, P]
    // p is exactly 0 outside 1..T_b (logits -1e30), so those positions add nothing whatever the prior says.
    out.kl_b = (p * (torch::log(p + kEps) - log_prior)).sum() * inv_b;
  }
  const Tensor usage = q.mean(std::vector<std::int64_t>{0, 1});
  out.usage_entropy = -(usage * torch::log(usage + kEps)).sum();
  out.total = out.nll_action + cfg.beta_s * out.nll_state + cfg.beta_z * out.kl_z + cfg.beta_b * out.kl_b -
              cfg.beta_usage * out.usage_entropy;
  out.boundary_ce = torch::zeros({});
  if (batch.supervise_boundaries && cfg.num_segments > 1) {
    for (int k = 0; k + 1 < cfg.num_segments; ++k) {
      const Tensor target = fixed_boundary(batch, k, batch.steps + 1);
      out.boundary_ce =
          out.boundary_ce -
          (torch::log_softmax(enc.boundary_logits[static_cast<std::size_t>(k)], -1) * target).sum() * inv_b;
    }
    out.total = out.total + out.boundary_ce;
  }
  out.unit_ce = unit_cross_entropy(batch, enc.latent_logits) * inv_b;
  out.total = out.total + cfg.warm_start_unit_weight * out.unit_ce;
  return out;
}

// The training-time encoder in eval mode: the definition hard_readout (compile_inference_torch.cpp) must match.
HardReadout hard_readout_reference(const CompileNetwork& net, const Batch& batch) {
  const Encoded enc = encode(net, batch, false, nullptr, false);
  HardReadout out;
  out.boundaries.resize(static_cast<std::size_t>(batch.size));
  out.skills.resize(static_cast<std::size_t>(batch.size));
  const Tensor ids = torch::stack(enc.latents, 1).argmax(-1).contiguous();  // [B, K]
  const auto acc = ids.accessor<std::int64_t, 2>();
  for (std::int64_t b = 0; b < batch.size; ++b) {
    const std::size_t src = batch.source[static_cast<std::size_t>(b)];
    std::vector<int> bounds = enc.position[static_cast<std::size_t>(b)];
    bounds.back() = static_cast<int>(batch.lengths[static_cast<std::size_t>(b)]);
    std::vector<int> skills;
    for (std::int64_t k = 0; k < ids.size(1); ++k) skills.push_back(static_cast<int>(acc[b][k]));
    out.boundaries[src] = std::move(bounds);
    out.skills[src] = std::move(skills);
  }
  return out;
}

}  // namespace sc::compile_detail
