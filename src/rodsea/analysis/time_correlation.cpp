#include "rodsea/analysis/time_correlation.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace rodsea {

void fft(std::vector<std::complex<double>>& a, bool inverse) {
    const std::size_t n = a.size();
    if (n == 0 || (n & (n - 1)) != 0) throw std::invalid_argument("fft: size not a power of two");
    for (std::size_t i = 1, j = 0; i < n; ++i) {
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1)
            j ^= bit;
        j ^= bit;
        if (i < j) std::swap(a[i], a[j]);
    }
    for (std::size_t len = 2; len <= n; len <<= 1) {
        const double angle = 2.0 * std::numbers::pi / static_cast<double>(len) * (inverse ? 1 : -1);
        const std::complex<double> step(std::cos(angle), std::sin(angle));
        for (std::size_t i = 0; i < n; i += len) {
            std::complex<double> w(1.0, 0.0);
            for (std::size_t k = 0; k < len / 2; ++k) {
                const std::complex<double> u = a[i + k], v = a[i + k + len / 2] * w;
                a[i + k] = u + v;
                a[i + k + len / 2] = u - v;
                w *= step;
            }
        }
    }
}

std::vector<double> orientation_autocorrelation(const std::vector<float>& angles,
                                                std::size_t frames, std::size_t bodies, int m,
                                                std::size_t max_lag) {
    if (frames == 0 || bodies == 0) return {};
    max_lag = std::min(max_lag, frames - 1);
    std::size_t size = 1;
    while (size <
           2 * frames)  // zero padding to 2T turns the circular correlation into a linear one
        size <<= 1;
    std::vector<double> sum(max_lag + 1, 0.0);
    std::vector<std::complex<double>> z(size);
    for (std::size_t b = 0; b < bodies; ++b) {
        std::fill(z.begin(), z.end(), std::complex<double>(0.0, 0.0));
        for (std::size_t t = 0; t < frames; ++t)
            z[t] = std::polar(1.0, m * static_cast<double>(angles[t * bodies + b]));
        fft(z, false);
        for (auto& v : z)
            v = std::norm(v);
        fft(z, true);
        for (std::size_t lag = 0; lag <= max_lag; ++lag)
            sum[lag] += z[lag].real() / static_cast<double>(size);
    }
    for (std::size_t lag = 0; lag <= max_lag; ++lag)
        sum[lag] /= static_cast<double>(bodies * (frames - lag));
    return sum;
}

}  // namespace rodsea
