#include "rodsea/analysis/time_correlation.hpp"

#include <fftw3.h>

#include <cmath>
#include <complex>
#include <memory>
#include <mutex>
#include <new>

#include "rodsea/analysis/statistics.hpp"

namespace rodsea {

namespace {

// FFTW's planner is not thread-safe; executing a plan is. Plans are made with FFTW_ESTIMATE,
// which picks the same algorithm every time: results do not depend on timing.
std::mutex planner;

struct BufferFree {
    void operator()(fftw_complex* p) const { fftw_free(p); }
};
struct PlanFree {
    void operator()(fftw_plan_s* p) const {
        const std::lock_guard lock(planner);
        fftw_destroy_plan(p);
    }
};
using Plan = std::unique_ptr<fftw_plan_s, PlanFree>;

Plan make_plan(std::size_t size, fftw_complex* data, int sign) {
    const std::lock_guard lock(planner);
    return Plan(fftw_plan_dft_1d(static_cast<int>(size), data, data, sign, FFTW_ESTIMATE));
}

}  // namespace

std::vector<double> orientation_autocorrelation(std::span<const float> angles, std::size_t frames,
                                                std::size_t bodies, int m, std::size_t max_lag) {
    if (frames == 0 || bodies == 0) return {};
    max_lag = std::min(max_lag, frames - 1);
    std::size_t size = 1;
    while (size <
           2 * frames)  // zero padding to 2T turns the circular correlation into a linear one
        size <<= 1;
    const std::unique_ptr<fftw_complex, BufferFree> buffer(fftw_alloc_complex(size));
    if (!buffer) throw std::bad_alloc();
    fftw_complex* z = buffer.get();
    const Plan forward = make_plan(size, z, FFTW_FORWARD),
               backward = make_plan(size, z, FFTW_BACKWARD);
    std::vector<double> sum(max_lag + 1, 0.0);
    for (std::size_t b = 0; b < bodies; ++b) {
        for (std::size_t t = 0; t < size; ++t) {
            const double theta = t < frames ? m * static_cast<double>(angles[t * bodies + b]) : 0.0;
            z[t][0] = t < frames ? std::cos(theta) : 0.0;
            z[t][1] = t < frames ? std::sin(theta) : 0.0;
        }
        fftw_execute(forward.get());
        for (std::size_t k = 0; k < size; ++k) {
            z[k][0] = z[k][0] * z[k][0] + z[k][1] * z[k][1];
            z[k][1] = 0.0;
        }
        fftw_execute(backward.get());
        for (std::size_t lag = 0; lag <= max_lag; ++lag)
            sum[lag] += z[lag][0] / static_cast<double>(size);
    }
    for (std::size_t lag = 0; lag <= max_lag; ++lag)
        sum[lag] /= static_cast<double>(bodies * (frames - lag));
    return sum;
}

std::size_t fit_lag_count(std::span<const double> c, double floor) {
    std::size_t n = 0;
    while (n + 1 < c.size() && c[n + 1] >= floor)
        ++n;
    return n;
}

double rotational_diffusion_from(std::span<const double> c, double interval, int m, double floor,
                                 std::size_t fit_lags) {
    std::vector<double> t, y;
    for (std::size_t lag = 1; lag <= fit_lags && lag < c.size(); ++lag) {
        if (!(c[lag] >= floor)) break;
        t.push_back(static_cast<double>(lag) * interval);
        y.push_back(-std::log(c[lag]));
    }
    if (t.empty()) return std::nan("");
    return slope_through_origin(t, y) / (m * m);
}

}  // namespace rodsea
