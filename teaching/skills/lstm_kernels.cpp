// LSTM step kernels (see lstm_kernels.hpp). exp and tanh are Cephes' single-precision approximations
// (~1-2 ulp). The AVX2 path and the portable path perform the same IEEE operations in the same order (no
// FMA contraction: the AVX2 code is compiled for "avx2" only), so both give bit-identical results and a
// model trains to the same bytes whichever path the CPU takes.
#include "teaching/skills/lstm_kernels.hpp"

#include <dlfcn.h>
#include <immintrin.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace sc::compile_detail {

namespace {

using SgemmFn = void (*)(const char*, const char*, const int*, const int*, const int*, const float*, const float*,
                         const int*, const float*, const int*, const float*, float*, const int*);

// LibTorch links the system BLAS (libblas.so.3); its Fortran sgemm_ is already in the process. Looking it up
// avoids linking a second BLAS and keeps products identical to torch's.
SgemmFn find_sgemm() {
  auto fn = reinterpret_cast<SgemmFn>(dlsym(RTLD_DEFAULT, "sgemm_"));
  if (fn == nullptr) throw std::runtime_error("sgemm_ not found: LibTorch's BLAS is not loaded");
  return fn;
}

constexpr float kExpHi = 88.3762626647949f, kExpLo = -88.3762626647949f;
constexpr float kLog2e = 1.44269504088896341f, kC1 = 0.693359375f, kC2 = -2.12194440e-4f;
constexpr float kP0 = 1.9875691500e-4f, kP1 = 1.3981999507e-3f, kP2 = 8.3334519073e-3f, kP3 = 4.1665795894e-2f,
                kP4 = 1.6666665459e-1f, kP5 = 5.0000001201e-1f;
constexpr float kT0 = -5.70498872745e-3f, kT1 = 2.06390887954e-2f, kT2 = -5.37397155531e-2f, kT3 = 1.33314422036e-1f,
                kT4 = -3.33332819422e-1f;
constexpr float kTanhSmall = 0.625f;  // below: odd polynomial; above: 1 - 2 / (exp(2x) + 1)

float exp_scalar(float x) {
  x = std::fmin(std::fmax(x, kExpLo), kExpHi);
  const float fx = std::floor(x * kLog2e + 0.5f);
  float r = x - fx * kC1;
  r = r - fx * kC2;
  float y = kP0;
  y = y * r + kP1;
  y = y * r + kP2;
  y = y * r + kP3;
  y = y * r + kP4;
  y = y * r + kP5;
  y = y * (r * r) + r + 1.0f;
  const std::int32_t bits = (static_cast<std::int32_t>(fx) + 127) << 23;
  float pow2;
  std::memcpy(&pow2, &bits, sizeof pow2);
  return y * pow2;
}

float sigmoid_scalar(float x) { return 1.0f / (1.0f + exp_scalar(-x)); }

float tanh_scalar(float x) {
  const float a = std::fabs(x);
  const float z = a * a;
  float p = kT0;
  p = p * z + kT1;
  p = p * z + kT2;
  p = p * z + kT3;
  p = p * z + kT4;
  const float small = p * z * a + a;
  const float large = 1.0f - 2.0f / (exp_scalar(a + a) + 1.0f);
  return std::copysign(a < kTanhSmall ? small : large, x);
}

__attribute__((target("avx2"))) __m256 exp_avx(__m256 x) {
  x = _mm256_min_ps(_mm256_max_ps(x, _mm256_set1_ps(kExpLo)), _mm256_set1_ps(kExpHi));
  const __m256 fx = _mm256_floor_ps(_mm256_add_ps(_mm256_mul_ps(x, _mm256_set1_ps(kLog2e)), _mm256_set1_ps(0.5f)));
  __m256 r = _mm256_sub_ps(x, _mm256_mul_ps(fx, _mm256_set1_ps(kC1)));
  r = _mm256_sub_ps(r, _mm256_mul_ps(fx, _mm256_set1_ps(kC2)));
  __m256 y = _mm256_set1_ps(kP0);
  for (float c : {kP1, kP2, kP3, kP4, kP5}) y = _mm256_add_ps(_mm256_mul_ps(y, r), _mm256_set1_ps(c));
  y = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(y, _mm256_mul_ps(r, r)), r), _mm256_set1_ps(1.0f));
  const __m256i bits = _mm256_slli_epi32(_mm256_add_epi32(_mm256_cvttps_epi32(fx), _mm256_set1_epi32(127)), 23);
  return _mm256_mul_ps(y, _mm256_castsi256_ps(bits));
}

__attribute__((target("avx2"))) __m256 sigmoid_avx(__m256 x) {
  const __m256 one = _mm256_set1_ps(1.0f);
  return _mm256_div_ps(one, _mm256_add_ps(one, exp_avx(_mm256_sub_ps(_mm256_setzero_ps(), x))));
}

__attribute__((target("avx2"))) __m256 tanh_avx(__m256 x) {
  const __m256 sign = _mm256_set1_ps(-0.0f);
  const __m256 a = _mm256_andnot_ps(sign, x);
  const __m256 z = _mm256_mul_ps(a, a);
  __m256 p = _mm256_set1_ps(kT0);
  for (float c : {kT1, kT2, kT3, kT4}) p = _mm256_add_ps(_mm256_mul_ps(p, z), _mm256_set1_ps(c));
  const __m256 small = _mm256_add_ps(_mm256_mul_ps(_mm256_mul_ps(p, z), a), a);
  const __m256 one = _mm256_set1_ps(1.0f);
  const __m256 e = exp_avx(_mm256_add_ps(a, a));
  const __m256 large = _mm256_sub_ps(one, _mm256_div_ps(_mm256_set1_ps(2.0f), _mm256_add_ps(e, one)));
  const __m256 mag = _mm256_blendv_ps(large, small, _mm256_cmp_ps(a, _mm256_set1_ps(kTanhSmall), _CMP_LT_OQ));
  return _mm256_or_ps(mag, _mm256_and_ps(sign, x));
}

const bool kHasAvx2 = __builtin_cpu_supports("avx2");

// y[i] = f(x[i]), 8 lanes at a time, the tail with the scalar twin (same operations).
__attribute__((target("avx2"))) void sigmoid_span_avx(const float* x, float* y, std::int64_t count) {
  std::int64_t i = 0;
  for (; i + 8 <= count; i += 8) _mm256_storeu_ps(y + i, sigmoid_avx(_mm256_loadu_ps(x + i)));
  for (; i < count; ++i) y[i] = sigmoid_scalar(x[i]);
}

__attribute__((target("avx2"))) void tanh_span_avx(const float* x, float* y, std::int64_t count) {
  std::int64_t i = 0;
  for (; i + 8 <= count; i += 8) _mm256_storeu_ps(y + i, tanh_avx(_mm256_loadu_ps(x + i)));
  for (; i < count; ++i) y[i] = tanh_scalar(x[i]);
}

void sigmoid_span(const float* x, float* y, std::int64_t count) {
  if (kHasAvx2) return sigmoid_span_avx(x, y, count);
  for (std::int64_t i = 0; i < count; ++i) y[i] = sigmoid_scalar(x[i]);
}

void tanh_span(const float* x, float* y, std::int64_t count) {
  if (kHasAvx2) return tanh_span_avx(x, y, count);
  for (std::int64_t i = 0; i < count; ++i) y[i] = tanh_scalar(x[i]);
}

}  // namespace

void blas_sgemm(char trans_a, char trans_b, std::int64_t m, std::int64_t n, std::int64_t k, float alpha, const float* a,
                std::int64_t lda, const float* b, std::int64_t ldb, float beta, float* c, std::int64_t ldc) {
  static const SgemmFn sgemm = find_sgemm();
  if (m == 0 || n == 0) return;
  const int mi = static_cast<int>(m), ni = static_cast<int>(n), ki = static_cast<int>(k);
  const int la = static_cast<int>(lda), lb = static_cast<int>(ldb), lc = static_cast<int>(ldc);
  sgemm(&trans_a, &trans_b, &mi, &ni, &ki, &alpha, a, &la, b, &lb, &beta, c, &lc);
}

void activate_gates(float* gates, std::int64_t n, std::int64_t hid) {
  for (std::int64_t r = 0; r < n; ++r) {
    float* g = gates + r * 4 * hid;
    sigmoid_span(g, g, 3 * hid);
    tanh_span(g + 3 * hid, g + 3 * hid, hid);
  }
}

void tanh_rows(const float* x, float* y, std::int64_t count) { tanh_span(x, y, count); }

void lstm_step_rows(const float* h_prev, const float* c_prev, const float* w_hh, const float* mask, std::int64_t n,
                    std::int64_t hid, const LstmStepRows& rows) {
  if (n == 0) return;
  // Row-major [n, 4H] += [n, H] x [4H, H]^T is, column-major, G^T += W_hh^T-as-stored (H x 4H, transposed)
  // times h_prev^T (H x n): the very call torch's addmm makes for these operands.
  blas_sgemm('T', 'N', 4 * hid, n, hid, 1.0f, w_hh, hid, h_prev, hid, 1.0f, rows.gates, 4 * hid);
  activate_gates(rows.gates, n, hid);
  for (std::int64_t r = 0; r < n; ++r) {
    const float* g = rows.gates + r * 4 * hid;
    float* cr = rows.c_raw + r * hid;
    const float* cp = c_prev + r * hid;
    for (std::int64_t j = 0; j < hid; ++j) cr[j] = g[hid + j] * cp[j] + g[j] * g[3 * hid + j];
  }
  tanh_rows(rows.c_raw, rows.tanh_c, n * hid);
  for (std::int64_t r = 0; r < n; ++r) {
    const float scale = mask != nullptr ? mask[r] : 1.0f;
    const float* g = rows.gates + r * 4 * hid;
    const float* tc = rows.tanh_c + r * hid;
    const float* cr = rows.c_raw + r * hid;
    float* ho = rows.h_out + r * hid;
    float* co = rows.c_out + r * hid;
    for (std::int64_t j = 0; j < hid; ++j) {
      ho[j] = scale * g[2 * hid + j] * tc[j];
      co[j] = scale * cr[j];
    }
  }
}

}  // namespace sc::compile_detail
