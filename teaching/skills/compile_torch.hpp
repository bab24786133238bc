#pragma once
// INTERNAL to teaching/skills/*_torch.cpp: the CompILE network in LibTorch. Never include this from a file
// that is not itself a *_torch.cpp (public headers stay torch-free; CompileModel is the pimpl facade).
#include <torch/torch.h>

#include <string>
#include <utility>
#include <vector>

#include "teaching/skills/compile_config.hpp"
#include "teaching/skills/compile_model.hpp"
#include "teaching/skills/model_steps.hpp"

namespace sc::compile_detail {

// ---- packed sequences -------------------------------------------------------------------------------
// Rows are sorted by needed length (longest first), so at step t the rows still running are a prefix of
// `active[t]` rows; a packed tensor stores step 0's active rows, then step 1's, ... (like PyTorch's
// PackedSequence). Work and memory are then proportional to the real number of steps, not to R x T_max.
struct Packing {
  std::vector<std::int64_t> active;  // rows running at each step (non-increasing)
  std::vector<std::int64_t> offset;  // first packed index of each step; offset.back() = total
  std::int64_t rows = 0;
  std::int64_t total() const { return offset.empty() ? 0 : offset.back(); }
  static Packing from_lengths(const std::vector<std::int64_t>& sorted_lengths_desc);
};

// LSTM over a packed sequence as ONE autograd node with a hand-written backward (BPTT). A per-step
// autograd graph (the reference's way) costs ~10 graph nodes per step and its backward re-materialises
// whole-sequence zero gradients; this is the main reason our training is fast.
//   xproj [N, 4H]: inputs already multiplied by W_ih plus both biases, gate order (i, f, o, g).
//   h0, c0 [rows, H] or undefined (zeros). w_hh [4H, H].
//   mask [N] or undefined: after each step h and c are multiplied by the row's mask value (CompILE's
//   soft reset before the previous boundary, reference-facts §3.4 step 1); gradients flow into the mask.
// Returns h [N, H] (after masking).
// Buffers of one packed LSTM run; step() advances it by one step (also usable without autograd, e.g. for
// an open-loop decoder whose next input depends on the previous output).
struct PackedLstmRun {
  torch::Tensor gates, c_raw, tanh_c, h_out, c_out;  // [N, 4H] activated (i, f, o, g); [N, H] each
  PackedLstmRun() = default;
  PackedLstmRun(const Packing& packing, std::int64_t hidden, const torch::TensorOptions& options);
  // Step t from the projected inputs of its active rows; h_init/c_init [rows, H] feed step 0.
  void step(const Packing& packing, std::size_t t, const torch::Tensor& xproj_t, const torch::Tensor& h_init,
            const torch::Tensor& c_init, const torch::Tensor& w_hh, const torch::Tensor& mask);
  // The same on raw contiguous data: xproj_t [active, 4H], mask [N] (whole packed mask) or null.
  void step(const Packing& packing, std::size_t t, const float* xproj_t, const float* h_init, const float* c_init,
            const float* w_hh, const float* mask);
};
// `replay`: a run already computed with the same inputs; its buffers are reused instead of recomputing
// the recurrence (the decoder computes its steps once, without autograd, to know its own feedback).
torch::Tensor packed_lstm(const torch::Tensor& xproj, const torch::Tensor& h0, const torch::Tensor& c0,
                          const torch::Tensor& w_hh, const torch::Tensor& mask, const Packing& packing,
                          PackedLstmRun* replay = nullptr);

// ---- parameters ---------------------------------------------------------------------------------------
struct Linear {
  torch::Tensor weight, bias;
  torch::Tensor operator()(const torch::Tensor& x) const { return torch::linear(x, weight, bias); }
};
struct Mlp {  // Linear - ReLU - Linear (every MLP of the reference)
  Linear first, second;
  torch::Tensor operator()(const torch::Tensor& x) const { return second(torch::relu(first(x))); }
};

// Same tensors as the reference's state_dict (§3.8), except the two LSTM biases are summed and the gate
// rows are ordered (i, f, o, g) so one sigmoid covers three gates.
struct CompileNetwork {
  CompileConfig config;
  Mlp enc_state, enc_action;  // encoder embeddings (state MLP only in state modes)
  Linear enc_ih;              // LSTM input weights + summed biases
  torch::Tensor enc_hh;
  Mlp head_b, head_z;
  Linear dec_1, dec_1a, dec_1b;  // z -> initial decoder (h, c)
  Mlp dec_state, dec_action;
  Linear dec_ih;
  torch::Tensor dec_hh;
  Mlp head_action, head_state;

  // PyTorch's default init (uniform +-1/sqrt(fan_in); LSTM +-1/sqrt(H)) drawn from `generator`.
  CompileNetwork(const CompileConfig& config, at::Generator& generator);
  // Name -> tensor, in a fixed order (file format and optimizer).
  std::vector<std::pair<std::string, torch::Tensor*>> named();
  std::vector<torch::Tensor> parameters();
};

// ---- batches ------------------------------------------------------------------------------------------
struct Batch {
  std::int64_t size = 0;              // B
  std::int64_t steps = 0;             // T_max (model steps)
  std::vector<std::int64_t> lengths;  // sorted longest first
  std::vector<std::size_t> source;    // batch row -> index in the caller's list
  torch::Tensor states;               // [T_max + 1, B, S] zero-padded (time-major; last step always padding)
  torch::Tensor actions;              // [T_max + 1, B, A]
  Packing encoder;                    // row b runs steps 0..lengths[b] (the extra step reads padding)
  torch::Tensor pack_index;           // [N] packed entry -> t * B + b
  torch::Tensor unpack_index;         // [(T_max+1) * B] -> packed entry, or N for "not computed"
  // Diagnostic (CompileTrainer::fix_boundaries): [B][K-1] boundary positions 1..T_b in model steps, used
  // instead of sampled boundaries; empty = boundaries are sampled as usual.
  std::vector<std::vector<int>> fixed_boundaries;
  // Warm start: the loss also pulls the boundary head towards fixed_boundaries (cross-entropy).
  bool supervise_boundaries = false;
  // Warm start with CompileConfig::warm_start_units: [B][K] the repeated unit of each segment (its target
  // skill), -1 for none; empty = no unit term.
  std::vector<std::vector<int>> segment_units;
};
// `steps[i]` must match the config's dimensions and have length >= 1. `fixed_boundaries`, when not empty,
// is parallel to `steps`: each K-1 positions in model steps (see Batch::fixed_boundaries).
Batch make_batch(const std::vector<const StepSequence*>& steps, const CompileConfig& config,
                 const std::vector<const std::vector<int>*>& fixed_boundaries = {});

// The actions the encoder embeds: the batch's, or zeros when CompileConfig::encoder_reads_actions is off.
torch::Tensor encoder_actions(const CompileNetwork& net, const Batch& batch);

// Decoder pass 1 (no autograd): open-loop steps from (h_init, c_init) [rows, H] over `packing`, writing each
// step's input into fb_action [N, A] / fb_state [N, S] (zero at step 0; fb_state unused without states) and
// the LSTM buffers into `run`.
void run_decoder_feedback(const CompileNetwork& net, const Packing& packing, const torch::Tensor& h_init,
                          const torch::Tensor& c_init, torch::Tensor& fb_action, torch::Tensor& fb_state,
                          PackedLstmRun& run);

// ---- forward pass -------------------------------------------------------------------------------------
struct LossTerms {
  torch::Tensor total, nll_action, nll_state, kl_z, kl_b;  // scalars (mean over the batch)
  torch::Tensor boundary_ce;    // Batch::supervise_boundaries only (else 0): -log p(fixed boundary), summed over k
  torch::Tensor usage_entropy;  // entropy of the batch's mean latent posterior (CompileConfig::beta_usage)
  torch::Tensor unit_ce;        // Batch::segment_units only (else 0): -log q(unit's skill), summed over segments
};
struct HardReadout {
  std::vector<std::vector<int>> boundaries;  // [B][K] in model steps; the last equals the length
  std::vector<std::vector<int>> skills;      // [B][K]
};

// A Gumbel-softmax sample (temperature 1) of a categorical latent with logits [B, M]; with `straight_through`
// its one-hot argmax in the forward pass and the relaxed sample's gradient in the backward pass
// (CompileConfig::straight_through_latents).
torch::Tensor relaxed_latent(const torch::Tensor& logits, at::Generator* generator, bool straight_through);
// Training (relaxed Gumbel-softmax samples drawn from `generator`) or evaluation (hard argmax, generator
// unused) losses of one batch.
LossTerms compute_losses(const CompileNetwork& net, const Batch& batch, bool relaxed, at::Generator* generator);
// Inference: encoder and heads only (no decoder), hard argmax; rows in the caller's order. The fast path
// (each pass runs from its hard start, raw-row LSTM steps); hard_readout_reference computes the same through
// the training-time encoder and is kept to test that they agree exactly.
HardReadout hard_readout(const CompileNetwork& net, const Batch& batch);
HardReadout hard_readout_reference(const CompileNetwork& net, const Batch& batch);

}  // namespace sc::compile_detail

namespace sc {
struct CompileModel::Impl {
  compile_detail::CompileNetwork net;
};
// Validates dimensions and converts to model steps (resampling per the config, from `phase`).
std::vector<ModelSteps> to_model_inputs(const std::vector<StepSequence>& trajectories, const CompileConfig& config,
                                        const std::string& what, double phase = 0.0);
}  // namespace sc
