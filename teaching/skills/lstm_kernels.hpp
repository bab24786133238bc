#pragma once
// Torch-free kernels of one LSTM step on raw float rows, shared by the packed LSTM (training) and the
// CompILE inference path. At CompILE's sizes (a handful of rows, H = 64) a torch op costs more in dispatch
// than in arithmetic, and an LSTM step was ~10 torch ops; these run the same math as plain calls.
#include <cstdint>

namespace sc::compile_detail {

// C = alpha * op(A) * op(B) + beta * C in BLAS column-major convention, through the sgemm_ of the BLAS that
// LibTorch itself uses (OpenBLAS here), so a product gives exactly what the equivalent torch op gives.
// trans_a/trans_b: 'N' or 'T'.
void blas_sgemm(char trans_a, char trans_b, std::int64_t m, std::int64_t n, std::int64_t k, float alpha, const float* a,
                std::int64_t lda, const float* b, std::int64_t ldb, float beta, float* c, std::int64_t ldc);

// Row-major rows [n, 4H] of pre-activations (i, f, o, g): sigmoid on i, f, o and tanh on g, in place.
void activate_gates(float* gates, std::int64_t n, std::int64_t hid);
// y[i] = tanh(x[i]) (x may equal y).
void tanh_rows(const float* x, float* y, std::int64_t count);

// Buffers of one step over n rows of H units, all row-major and contiguous.
struct LstmStepRows {
  float* gates;   // [n, 4H] in: x W_ih^T + b (projected input); out: activated gates
  float* c_raw;   // [n, H] cell before masking
  float* tanh_c;  // [n, H] tanh(c_raw)
  float* h_out;   // [n, H] masked h
  float* c_out;   // [n, H] masked c
};
// One LSTM step: gates += h_prev W_hh^T, activations, c = f c_prev + i g, h = o tanh(c), then h and c times
// the row's mask value (mask null = no masking). h_prev/c_prev [n, H], w_hh [4H, H].
void lstm_step_rows(const float* h_prev, const float* c_prev, const float* w_hh, const float* mask, std::int64_t n,
                    std::int64_t hid, const LstmStepRows& rows);

}  // namespace sc::compile_detail
