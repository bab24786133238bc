// Pass 1 of the CompILE decoder (see decode() in compile_forward_torch.cpp): the open-loop steps, run on raw
// rows to learn what each step feeds back. Per step the decoder is ~8 small layers (embeddings, input
// projection, LSTM, output heads); as torch ops that was ~25 dispatches per step, more than the arithmetic.
// Each layer here is the sgemm call torch::linear makes (bias rows, then C += x W^T), so the products are the
// same numbers; tanh is lstm_kernels' approximation.
#include <algorithm>
#include <cstring>

#include "teaching/skills/compile_torch.hpp"
#include "teaching/skills/lstm_kernels.hpp"

namespace sc::compile_detail {

namespace {

// y[n, out] (row stride ldy) = x[n, in] W^T + b.
void linear_rows(const Linear& l, const float* x, std::int64_t n, float* y, std::int64_t ldy) {
  const std::int64_t out = l.weight.size(0), in = l.weight.size(1);
  const float* b = l.bias.data_ptr<float>();
  for (std::int64_t r = 0; r < n; ++r) std::memcpy(y + r * ldy, b, sizeof(float) * static_cast<std::size_t>(out));
  blas_sgemm('T', 'N', out, n, in, 1.0f, l.weight.data_ptr<float>(), in, x, in, 1.0f, y, ldy);
}

// y = second(relu(first(x))); `mid` holds n x first-width floats.
void mlp_rows(const Mlp& m, const float* x, std::int64_t n, float* mid, float* y, std::int64_t ldy) {
  const std::int64_t width = m.first.weight.size(0);
  linear_rows(m.first, x, n, mid, width);
  for (std::int64_t i = 0; i < n * width; ++i) mid[i] = std::max(mid[i], 0.0f);
  linear_rows(m.second, mid, n, y, ldy);
}

}  // namespace

void run_decoder_feedback(const CompileNetwork& net, const Packing& packing, const torch::Tensor& h_init,
                          const torch::Tensor& c_init, torch::Tensor& fb_action, torch::Tensor& fb_state,
                          PackedLstmRun& run) {
  const auto& cfg = net.config;
  const bool states = cfg.uses_states();
  const std::int64_t hid = cfg.hidden, rows = packing.rows, a_dim = fb_action.size(1), s_dim = fb_state.size(1);
  const std::int64_t emb = net.dec_action.second.weight.size(0);
  std::vector<float> mid(static_cast<std::size_t>(rows * hid)), x(mid.size()), xproj(4 * mid.size());
  float* fa = fb_action.data_ptr<float>();
  float* fs = fb_state.data_ptr<float>();
  const float* hi = h_init.data_ptr<float>();
  const float* ci = c_init.data_ptr<float>();
  const float* w_hh = net.dec_hh.data_ptr<float>();
  for (std::size_t j = 0; j < packing.active.size(); ++j) {
    const std::int64_t n = packing.active[j], off = packing.offset[j];
    // Input: [action embedding, state embedding] of the previous output (action first, §3.3).
    mlp_rows(net.dec_action, fa + off * a_dim, n, mid.data(), x.data(), hid);
    if (states) mlp_rows(net.dec_state, fs + off * s_dim, n, mid.data(), x.data() + emb, hid);
    linear_rows(net.dec_ih, x.data(), n, xproj.data(), 4 * hid);
    run.step(packing, j, xproj.data(), hi, ci, w_hh, nullptr);
    if (j + 1 == packing.active.size()) break;
    // Feedback for the rows still running at the next step: tanh(head_action(h)) and head_state(h).
    const std::int64_t next = packing.offset[j + 1], n_next = packing.active[j + 1];
    const float* h = run.h_out.data_ptr<float>() + off * hid;
    mlp_rows(net.head_action, h, n_next, mid.data(), fa + next * a_dim, a_dim);
    tanh_rows(fa + next * a_dim, fa + next * a_dim, n_next * a_dim);
    if (states) mlp_rows(net.head_state, h, n_next, mid.data(), fs + next * s_dim, s_dim);
  }
}

}  // namespace sc::compile_detail
