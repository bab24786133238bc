// CompILE inference (hard_readout): the encoder's K passes with hard boundaries, no decoder, no autograd.
// It gives exactly what the training-time encoder (compile_forward_torch.cpp, hard_readout_reference) gives
// in eval mode, which a test checks, but costs a fraction:
//  * with a hard (one-hot) boundary the mask of pass k is 0 before start_k = max of the earlier boundaries
//    and 1 from there on, so before start_k the masked state is exactly zero and the pass is an LSTM started
//    from zero state at start_k: each row runs only from its own start (the outputs before it are zero
//    rows, still scored, since the reference lets a later boundary fall before an earlier one);
//  * the recurrence runs on raw rows (lstm_kernels) instead of ~10 dispatched torch ops per step;
//  * the heads stay torch ops over the same shapes as the reference path (one call per pass), so the
//    logits are the very same numbers.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "teaching/skills/compile_torch.hpp"
#include "teaching/skills/lstm_kernels.hpp"

namespace sc::compile_detail {

namespace {

using torch::Tensor;

// Index of the first maximum of v[first..last] (torch's argmax rule: NaN counts as the maximum).
std::int64_t first_argmax(const float* v, std::int64_t first, std::int64_t last) {
  std::int64_t best = first;
  for (std::int64_t i = first + 1; i <= last; ++i) {
    if (std::isnan(v[best])) break;
    if (v[i] > v[best] || std::isnan(v[i])) best = i;
  }
  return best;
}

// Scratch rows of one encoder pass: row r's state and the gathered rows of the current step.
struct PassScratch {
  std::vector<float> h, c;                         // [B, H] state of each row after its last step
  std::vector<float> gates, h_prev, c_prev;        // [B, 4H], [B, H], [B, H] gathered active rows
  std::vector<float> c_raw, tanh_c, h_out, c_out;  // [B, H] step outputs
  std::vector<std::int64_t> rows;                  // batch rows running at this step
  PassScratch(std::int64_t b, std::int64_t hid)
      : h(static_cast<std::size_t>(b * hid)),
        c(h.size()),
        gates(4 * h.size()),
        h_prev(h.size()),
        c_prev(h.size()),
        c_raw(h.size()),
        tanh_c(h.size()),
        h_out(h.size()),
        c_out(h.size()) {}
};

// One masked encoder pass with hard starts: fills e [N, H] (packed like xproj; zero before each row's start)
// for steps 0..last_step[r] of each row.
void run_pass(const Batch& batch, const float* xproj, const float* w_hh, std::int64_t hid,
              const std::vector<std::int64_t>& start, const std::vector<std::int64_t>& last_step, float* e,
              PassScratch& s) {
  const Packing& p = batch.encoder;
  const std::size_t row_bytes = sizeof(float) * static_cast<std::size_t>(hid);
  const std::int64_t first = *std::min_element(start.begin(), start.end());
  for (std::size_t t = static_cast<std::size_t>(first); t < p.active.size(); ++t) {
    const auto ti = static_cast<std::int64_t>(t);
    s.rows.clear();
    for (std::int64_t r = 0; r < p.active[t]; ++r)
      if (start[static_cast<std::size_t>(r)] <= ti && ti <= last_step[static_cast<std::size_t>(r)]) s.rows.push_back(r);
    const auto n = static_cast<std::int64_t>(s.rows.size());
    if (n == 0) continue;
    for (std::int64_t i = 0; i < n; ++i) {
      const std::int64_t r = s.rows[static_cast<std::size_t>(i)];
      std::memcpy(&s.gates[static_cast<std::size_t>(i * 4 * hid)], xproj + (p.offset[t] + r) * 4 * hid, 4 * row_bytes);
      const bool fresh = ti == start[static_cast<std::size_t>(r)];  // the masked state before start is zero
      float* hp = &s.h_prev[static_cast<std::size_t>(i * hid)];
      float* cp = &s.c_prev[static_cast<std::size_t>(i * hid)];
      if (fresh) {
        std::fill(hp, hp + hid, 0.0f);
        std::fill(cp, cp + hid, 0.0f);
      } else {
        std::memcpy(hp, &s.h[static_cast<std::size_t>(r * hid)], row_bytes);
        std::memcpy(cp, &s.c[static_cast<std::size_t>(r * hid)], row_bytes);
      }
    }
    lstm_step_rows(s.h_prev.data(), s.c_prev.data(), w_hh, nullptr, n, hid,
                   {s.gates.data(), s.c_raw.data(), s.tanh_c.data(), s.h_out.data(), s.c_out.data()});
    for (std::int64_t i = 0; i < n; ++i) {
      const std::int64_t r = s.rows[static_cast<std::size_t>(i)];
      const float* ho = &s.h_out[static_cast<std::size_t>(i * hid)];
      std::memcpy(&s.h[static_cast<std::size_t>(r * hid)], ho, row_bytes);
      std::memcpy(&s.c[static_cast<std::size_t>(r * hid)], &s.c_out[static_cast<std::size_t>(i * hid)], row_bytes);
      std::memcpy(e + (p.offset[t] + r) * hid, ho, row_bytes);
    }
  }
}

// Projected encoder inputs [N, 4H], packed: the same ops as the reference encoder, hence the same numbers.
Tensor project_inputs(const CompileNetwork& net, const Batch& batch) {
  const auto& cfg = net.config;
  const std::int64_t positions = batch.steps + 1;
  Tensor x = net.enc_action(encoder_actions(net, batch));
  if (cfg.uses_states()) x = torch::cat({net.enc_state(batch.states), x}, -1);  // state first (§3.3)
  return net.enc_ih(x.view({positions * batch.size, cfg.hidden}).index_select(0, batch.pack_index)).contiguous();
}

// Hard boundary of pass k < K-1 for every row: the first argmax of the logits over positions 1..T_b
// (position t = encoder step t; the -1e30 mask of the reference excludes exactly the other positions).
std::vector<std::int64_t> boundaries(const CompileNetwork& net, const Batch& batch, const Tensor& e) {
  const Tensor logits = net.head_b(e).contiguous();  // [N, 1]: zero rows before a start are scored too
  const float* lp = logits.data_ptr<float>();
  std::vector<std::int64_t> out(static_cast<std::size_t>(batch.size));
  std::vector<float> row;
  for (std::int64_t r = 0; r < batch.size; ++r) {
    const std::int64_t len = batch.lengths[static_cast<std::size_t>(r)];
    row.assign(static_cast<std::size_t>(len + 1), 0.0f);
    for (std::int64_t t = 1; t <= len; ++t)
      row[static_cast<std::size_t>(t)] = lp[batch.encoder.offset[static_cast<std::size_t>(t)] + r];
    out[static_cast<std::size_t>(r)] = first_argmax(row.data(), 1, len);
  }
  return out;
}

// Skill of each row's segment: argmax of head_z at the encoding one step before the boundary (a zero row if
// that step is before the row's start, as in the reference).
std::vector<std::int64_t> skills(const CompileNetwork& net, const Batch& batch, const Tensor& e,
                                 const std::vector<std::int64_t>& position) {
  const std::int64_t hid = e.size(1);
  Tensor readout = torch::empty({batch.size, hid});
  for (std::int64_t r = 0; r < batch.size; ++r) {
    const std::int64_t step = position[static_cast<std::size_t>(r)] - 1;
    const float* src = e.data_ptr<float>() + (batch.encoder.offset[static_cast<std::size_t>(step)] + r) * hid;
    std::memcpy(readout.data_ptr<float>() + r * hid, src, sizeof(float) * static_cast<std::size_t>(hid));
  }
  const Tensor z_logits = net.head_z(readout).contiguous();
  const std::int64_t m = z_logits.size(1);
  std::vector<std::int64_t> out(static_cast<std::size_t>(batch.size));
  for (std::int64_t r = 0; r < batch.size; ++r)
    out[static_cast<std::size_t>(r)] = first_argmax(z_logits.data_ptr<float>() + r * m, 0, m - 1);
  return out;
}

}  // namespace

HardReadout hard_readout(const CompileNetwork& net, const Batch& batch) {
  c10::InferenceMode inference;
  const std::int64_t b_size = batch.size, hid = net.config.hidden;
  const int k_count = net.config.num_segments;
  const Tensor xproj = project_inputs(net, batch);
  const Tensor w_hh = net.enc_hh.contiguous();
  PassScratch scratch(b_size, hid);
  std::vector<std::int64_t> start(static_cast<std::size_t>(b_size), 0), last_step(start.size());
  HardReadout out;
  out.boundaries.assign(start.size(), std::vector<int>(static_cast<std::size_t>(k_count)));
  out.skills = out.boundaries;
  for (int k = 0; k < k_count; ++k) {
    const bool last_pass = k == k_count - 1;
    // Boundary logits need every step 0..T_b; the last pass (boundary T_b) is read out only at T_b - 1.
    for (std::int64_t r = 0; r < b_size; ++r)
      last_step[static_cast<std::size_t>(r)] = batch.lengths[static_cast<std::size_t>(r)] - (last_pass ? 1 : 0);
    Tensor e = torch::zeros({batch.encoder.total(), hid});
    run_pass(batch, xproj.data_ptr<float>(), w_hh.data_ptr<float>(), hid, start, last_step, e.data_ptr<float>(),
             scratch);
    const std::vector<std::int64_t> position =
        last_pass ? std::vector<std::int64_t>(batch.lengths.begin(), batch.lengths.end()) : boundaries(net, batch, e);
    const std::vector<std::int64_t> skill = skills(net, batch, e, position);
    for (std::int64_t r = 0; r < b_size; ++r) {
      const auto ri = static_cast<std::size_t>(r);
      const std::size_t src = batch.source[ri];  // rows back in the caller's order
      out.boundaries[src][static_cast<std::size_t>(k)] = static_cast<int>(position[ri]);
      out.skills[src][static_cast<std::size_t>(k)] = static_cast<int>(skill[ri]);
      start[ri] = std::max(start[ri], position[ri]);  // the next pass's mask is 0 before this
    }
  }
  return out;
}

}  // namespace sc::compile_detail
