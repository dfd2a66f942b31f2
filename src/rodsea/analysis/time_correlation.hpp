#pragma once
// Orientational autocorrelation C_m(τ) = ⟨cos m(θ_i(t+τ) − θ_i(t))⟩ over bodies i and every time
// origin t, and the rotational diffusion coefficient from it (docs/model.md §4).
#include <cstddef>
#include <span>
#include <vector>

namespace rodsea {

// angles[frame * bodies + body] (rad), frames equally spaced. Returns C(lag) for lag = 0 ..
// max_lag (frames), each averaged over bodies and all the origins that lag allows. Per body,
// Σ_t z(t+τ) z̄(t) with z = e^{imθ} is one autocorrelation, computed by FFT (FFTW): O(T log T)
// instead of O(T²), which keeps 10⁵ bodies × 10³ frames in seconds.
std::vector<double> orientation_autocorrelation(std::span<const float> angles, std::size_t frames,
                                                std::size_t bodies, int m, std::size_t max_lag);

// The lags the D_r fit uses on a curve: 1 .. n where C stays ≥ floor from lag 1 on.
std::size_t fit_lag_count(std::span<const double> c, double floor);

// D_r from C sampled every `interval` seconds: the least-squares fit of −ln C = m² D_r t through
// the origin over lags 1 .. fit_lags (stopping early where C < floor). NaN when no lag qualifies.
double rotational_diffusion_from(std::span<const double> c, double interval, int m, double floor,
                                 std::size_t fit_lags);

}  // namespace rodsea
