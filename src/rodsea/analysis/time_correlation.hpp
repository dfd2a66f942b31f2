#pragma once
// Orientational autocorrelation C_m(τ) = ⟨cos m(θ_i(t+τ) − θ_i(t))⟩ over bodies i and every time
// origin t, through the FFT: per body, Σ_t z(t+τ) z̄(t) with z = e^{imθ} is one autocorrelation,
// O(T log T) instead of O(T²), which keeps 10⁵ bodies × 10³ frames in seconds.
#include <complex>
#include <cstddef>
#include <vector>

namespace rodsea {

// In-place radix-2 FFT; `data.size()` must be a power of two. inverse: e^{+i...}, unscaled.
void fft(std::vector<std::complex<double>>& data, bool inverse);

// angles[frame * bodies + body] (rad), frames equally spaced. Returns C(lag) for lag = 0 ..
// max_lag (frames), each averaged over bodies and all the origins that lag allows.
std::vector<double> orientation_autocorrelation(const std::vector<float>& angles,
                                                std::size_t frames, std::size_t bodies, int m,
                                                std::size_t max_lag);

}  // namespace rodsea
