// A masked LSTM over packed sequences with a hand-written backward pass (see compile_torch.hpp).
// Steps run on raw rows (lstm_kernels: the BLAS torch uses plus plain loops) because per-op dispatch, not
// arithmetic, dominates at these sizes.
#include "teaching/skills/compile_torch.hpp"

#include <algorithm>
#include <cstring>

#include "teaching/skills/lstm_kernels.hpp"

namespace sc::compile_detail {

Packing Packing::from_lengths(const std::vector<std::int64_t>& lengths) {
  Packing p;
  p.rows = static_cast<std::int64_t>(lengths.size());
  const std::int64_t steps = lengths.empty() ? 0 : lengths.front();
  p.active.assign(static_cast<std::size_t>(steps), 0);
  for (auto len : lengths)
    for (std::int64_t t = 0; t < len; ++t) ++p.active[static_cast<std::size_t>(t)];
  p.offset.resize(static_cast<std::size_t>(steps) + 1, 0);
  for (std::size_t t = 0; t < p.active.size(); ++t) p.offset[t + 1] = p.offset[t] + p.active[t];
  return p;
}

PackedLstmRun::PackedLstmRun(const Packing& packing, std::int64_t hid, const torch::TensorOptions& opts) {
  const std::int64_t n_total = packing.total();
  gates = torch::empty({n_total, 4 * hid}, opts);
  c_raw = torch::empty({n_total, hid}, opts);
  tanh_c = torch::empty({n_total, hid}, opts);
  h_out = torch::empty({n_total, hid}, opts);
  c_out = torch::empty({n_total, hid}, opts);
}

void PackedLstmRun::step(const Packing& packing, std::size_t t, const torch::Tensor& xproj_t,
                         const torch::Tensor& h_init, const torch::Tensor& c_init, const torch::Tensor& w_hh,
                         const torch::Tensor& mask) {
  TORCH_CHECK(xproj_t.is_contiguous() && h_init.is_contiguous() && c_init.is_contiguous() && w_hh.is_contiguous(),
              "PackedLstmRun::step needs contiguous tensors");
  const float* m = mask.defined() && mask.numel() > 0 ? mask.data_ptr<float>() : nullptr;
  step(packing, t, xproj_t.data_ptr<float>(), h_init.data_ptr<float>(), c_init.data_ptr<float>(),
       w_hh.data_ptr<float>(), m);
}

// Raw-pointer step: no torch op at all (the tensor version above costs only pointer look-ups), because ~10
// dispatched ops per step used to cost more than the step's arithmetic.
void PackedLstmRun::step(const Packing& packing, std::size_t t, const float* xproj_t, const float* h_init,
                         const float* c_init, const float* w_hh, const float* mask) {
  const std::int64_t n = packing.active[t], off = packing.offset[t], hid = h_out.size(1);
  if (n == 0) return;
  const std::int64_t prev = t == 0 ? 0 : packing.offset[t - 1] * hid;
  const float* h_prev = t == 0 ? h_init : h_out.data_ptr<float>() + prev;
  const float* c_prev = t == 0 ? c_init : c_out.data_ptr<float>() + prev;
  float* g = gates.data_ptr<float>() + off * 4 * hid;
  std::memcpy(g, xproj_t, sizeof(float) * static_cast<std::size_t>(n * 4 * hid));
  const LstmStepRows rows{g, c_raw.data_ptr<float>() + off * hid, tanh_c.data_ptr<float>() + off * hid,
                          h_out.data_ptr<float>() + off * hid, c_out.data_ptr<float>() + off * hid};
  lstm_step_rows(h_prev, c_prev, w_hh, mask != nullptr ? mask + off : nullptr, n, hid, rows);
}

namespace {

using torch::Tensor;
using torch::autograd::AutogradContext;
using torch::autograd::tensor_list;

class PackedLstmFunction : public torch::autograd::Function<PackedLstmFunction> {
 public:
  static Tensor forward(AutogradContext* ctx, Tensor xproj, Tensor h0, Tensor c0, Tensor w_hh, Tensor mask,
                        std::vector<std::int64_t> active, std::int64_t rows, PackedLstmRun* replay) {
    Packing local;
    local.active = std::move(active);
    local.rows = rows;
    local.offset.assign(local.active.size() + 1, 0);
    for (std::size_t t = 0; t < local.active.size(); ++t) local.offset[t + 1] = local.offset[t] + local.active[t];
    Tensor h_init = h0.contiguous();
    Tensor c_init = c0.contiguous();
    PackedLstmRun run;
    if (replay != nullptr) {
      run = *replay;  // the caller already ran these steps (same inputs); only the graph node is new
    } else {
      run = PackedLstmRun(local, w_hh.size(1), xproj.options());
      const float* m = mask.numel() > 0 ? mask.data_ptr<float>() : nullptr;
      const float* x = xproj.data_ptr<float>();
      const std::int64_t width = xproj.size(1);
      for (std::size_t t = 0; t < local.active.size(); ++t)
        run.step(local, t, x + local.offset[t] * width, h_init.data_ptr<float>(), c_init.data_ptr<float>(),
                 w_hh.data_ptr<float>(), m);
    }
    const Tensor gates = run.gates, c_raw = run.c_raw, tanh_c = run.tanh_c, h_out = run.h_out, c_out = run.c_out;
    ctx->save_for_backward({w_hh, h_init, c_init, mask});
    ctx->saved_data["gates"] = gates;
    ctx->saved_data["c_raw"] = c_raw;
    ctx->saved_data["tanh_c"] = tanh_c;
    // h_out is also this node's OUTPUT: storing that very tensor here would make output -> grad_fn -> ctx ->
    // output a reference cycle that leaks every iteration's whole graph (14 MB per iteration on the tiny
    // test config, 5.7 GB after 400 parking iterations). A detached alias shares the storage, not the cycle.
    ctx->saved_data["h_out"] = h_out.detach();
    ctx->saved_data["c_out"] = c_out;
    ctx->saved_data["active"] = local.active;
    ctx->saved_data["rows"] = rows;

    return h_out;
  }

  static tensor_list backward(AutogradContext* ctx, tensor_list grad_outputs) {
    const auto saved = ctx->get_saved_variables();
    const Tensor& w_hh = saved[0];
    const Tensor& h_init = saved[1];
    const Tensor& c_init = saved[2];
    const Tensor& mask = saved[3];
    const Tensor gates = ctx->saved_data["gates"].toTensor();
    const Tensor c_raw = ctx->saved_data["c_raw"].toTensor();
    const Tensor tanh_c = ctx->saved_data["tanh_c"].toTensor();
    const Tensor h_out = ctx->saved_data["h_out"].toTensor();
    const Tensor c_out = ctx->saved_data["c_out"].toTensor();
    Packing local;
    local.active = ctx->saved_data["active"].toIntVector();
    local.rows = ctx->saved_data["rows"].toInt();
    local.offset.assign(local.active.size() + 1, 0);
    for (std::size_t t = 0; t < local.active.size(); ++t) local.offset[t + 1] = local.offset[t] + local.active[t];
    const Packing* packing = &local;

    const std::int64_t hid = w_hh.size(1), n_total = packing->total();
    const auto opts = gates.options();
    Tensor grad_h_out = grad_outputs[0].defined() ? grad_outputs[0].contiguous() : torch::zeros({n_total, hid}, opts);
    Tensor d_gates = torch::zeros({n_total, 4 * hid}, opts);
    Tensor d_mask = mask.numel() > 0 ? torch::zeros({n_total}, opts) : Tensor();
    Tensor dh = torch::zeros({packing->rows, hid}, opts);  // gradient w.r.t. h_{t} (masked) from step t+1
    Tensor dc = torch::zeros({packing->rows, hid}, opts);
    const float* m = mask.numel() > 0 ? mask.data_ptr<float>() : nullptr;
    float* dm = d_mask.defined() ? d_mask.data_ptr<float>() : nullptr;

    for (std::size_t ti = packing->active.size(); ti-- > 0;) {
      const std::int64_t n = packing->active[ti], off = packing->offset[ti];
      if (n == 0) continue;
      const float* gp = gates.data_ptr<float>() + off * 4 * hid;
      const float* cr = c_raw.data_ptr<float>() + off * hid;
      const float* tc = tanh_c.data_ptr<float>() + off * hid;
      const float* gho = grad_h_out.data_ptr<float>() + off * hid;
      const float* cprev = ti == 0 ? c_init.data_ptr<float>() : c_out.data_ptr<float>() + packing->offset[ti - 1] * hid;
      float* dg = d_gates.data_ptr<float>() + off * 4 * hid;
      float* dhp = dh.data_ptr<float>();
      float* dcp = dc.data_ptr<float>();
      for (std::int64_t r = 0; r < n; ++r) {
        const float scale = m ? m[off + r] : 1.0f;
        const float* g = gp + r * 4 * hid;
        float* d = dg + r * 4 * hid;
        float dm_acc = 0.0f;
        for (std::int64_t j = 0; j < hid; ++j) {
          const std::int64_t k = r * hid + j;
          const float i = g[j], f = g[hid + j], o = g[2 * hid + j], gg = g[3 * hid + j];
          const float d_h = gho[k] + dhp[k];
          const float d_c_masked = dcp[k];
          dm_acc += d_h * o * tc[k] + d_c_masked * cr[k];
          const float d_ht = scale * d_h;
          float d_ct = scale * d_c_masked + d_ht * o * (1.0f - tc[k] * tc[k]);
          const float d_o = d_ht * tc[k];
          d[j] = d_ct * gg * i * (1.0f - i);
          d[hid + j] = d_ct * cprev[k] * f * (1.0f - f);
          d[2 * hid + j] = d_o * o * (1.0f - o);
          d[3 * hid + j] = d_ct * i * (1.0f - gg * gg);
          dcp[k] = d_ct * f;  // now the gradient w.r.t. c_{t-1}
        }
        if (dm) dm[off + r] = dm_acc;
      }
      // Gradient w.r.t. h_{t-1} for the rows that ran at step t (the others ended earlier and stay zero):
      // dh[n, H] = dG[n, 4H] W_hh[4H, H], i.e. column-major dh^T = W_hh^T-as-stored x dG^T (torch's mm call).
      blas_sgemm('N', 'N', hid, n, 4 * hid, 1.0f, w_hh.data_ptr<float>(), hid, dg, 4 * hid, 0.0f, dhp, hid);
    }

    // dW_hh = sum_t dG_t^T h_{t-1}: one product over the packed sequence instead of one per step.
    Tensor h_prev = torch::empty({n_total, hid}, opts);
    for (std::size_t t = 0; t < packing->active.size(); ++t) {
      const std::int64_t n = packing->active[t];
      if (n == 0) break;
      const float* src = t == 0 ? h_init.data_ptr<float>() : h_out.data_ptr<float>() + packing->offset[t - 1] * hid;
      std::memcpy(h_prev.data_ptr<float>() + packing->offset[t] * hid, src,
                  sizeof(float) * static_cast<std::size_t>(n * hid));
    }
    Tensor d_w_hh = d_gates.t().mm(h_prev);
    return {d_gates, dh, dc, d_w_hh, d_mask, Tensor(), Tensor(), Tensor()};
  }
};

}  // namespace

torch::Tensor packed_lstm(const torch::Tensor& xproj, const torch::Tensor& h0, const torch::Tensor& c0,
                          const torch::Tensor& w_hh, const torch::Tensor& mask, const Packing& packing,
                          PackedLstmRun* replay) {
  // Custom autograd functions reject undefined inputs: "no initial state" becomes zeros and "no mask" an
  // empty tensor.
  const torch::Tensor zeros = torch::zeros({packing.rows, w_hh.size(1)}, xproj.options());
  return PackedLstmFunction::apply(
      xproj.contiguous(), h0.defined() ? h0 : zeros, c0.defined() ? c0 : zeros, w_hh.contiguous(),
      mask.defined() ? mask.contiguous() : torch::empty({0}, xproj.options()), packing.active, packing.rows, replay);
}

}  // namespace sc::compile_detail
