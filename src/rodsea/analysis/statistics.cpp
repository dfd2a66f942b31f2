#include "rodsea/analysis/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>

#include "rodsea/random.hpp"

namespace rodsea {

double integrated_autocorrelation_time(std::span<const double> x) {
    const std::size_t n = x.size();
    if (n < 2) return 0.5;
    double mean = 0.0;
    for (double v : x)
        mean += v;
    mean /= static_cast<double>(n);
    double c0 = 0.0;
    for (double v : x)
        c0 += (v - mean) * (v - mean);
    c0 /= static_cast<double>(n);
    // Relative to the series' scale, a variance at rounding level is a constant series.
    if (!(c0 > 1e-28 * std::max(1.0, mean * mean))) return 0.5;
    double tau = 0.5;
    for (std::size_t t = 1; t < n; ++t) {
        double ct = 0.0;
        for (std::size_t i = 0; i + t < n; ++i)
            ct += (x[i] - mean) * (x[i + t] - mean);
        tau += ct / static_cast<double>(n) / c0;
        if (static_cast<double>(t) >= 5.0 * tau) break;
    }
    return std::max(tau, 0.5);
}

Estimate estimate_mean(std::span<const double> x) {
    Estimate e;
    e.samples = x.size();
    if (x.empty()) {
        e.mean = e.error = std::numeric_limits<double>::quiet_NaN();
        return e;
    }
    const double n = static_cast<double>(x.size());
    for (double v : x)
        e.mean += v;
    e.mean /= n;
    e.tau_int = integrated_autocorrelation_time(x);
    e.n_eff = n / (2.0 * e.tau_int);
    if (x.size() < 2) {
        e.error = std::numeric_limits<double>::quiet_NaN();
        return e;
    }
    double var = 0.0;
    for (double v : x)
        var += (v - e.mean) * (v - e.mean);
    var /= n - 1.0;
    e.error = std::sqrt(var * 2.0 * e.tau_int / n);
    return e;
}

Estimate estimate_from_blocks(double full, std::span<const double> blocks) {
    Estimate e;
    e.from_blocks = true;
    e.mean = full;
    e.samples = blocks.size();
    e.n_eff = static_cast<double>(blocks.size());
    std::vector<double> finite;
    for (double b : blocks)
        if (std::isfinite(b)) finite.push_back(b);
    if (finite.size() < 2) {
        e.error = std::numeric_limits<double>::quiet_NaN();
        return e;
    }
    double mean = 0.0, var = 0.0;
    for (double b : finite)
        mean += b;
    mean /= static_cast<double>(finite.size());
    for (double b : finite)
        var += (b - mean) * (b - mean);
    var /= static_cast<double>(finite.size() - 1);
    e.error = std::sqrt(var / static_cast<double>(finite.size()));
    return e;
}

std::size_t steady_start(std::span<const double> x) {
    const std::size_t n = x.size();
    if (n < 4) return 0;
    const std::size_t stride = std::max<std::size_t>(1, n / 50);
    std::size_t best = 0;
    double best_neff = -1.0;
    for (std::size_t t0 = 0; t0 <= n / 2; t0 += stride) {
        const double neff =
            static_cast<double>(n - t0) / (2.0 * integrated_autocorrelation_time(x.subspan(t0)));
        if (neff > best_neff) {  // strict: ties keep the earliest start
            best_neff = neff;
            best = t0;
        }
    }
    return best;
}

namespace {

// P(a, x), the regularised lower incomplete gamma function, by its power series (whose terms
// shrink once n > x − a; a few hundred terms for the degrees of freedom of any replicate set).
double regularized_lower_gamma(double a, double x) {
    if (x <= 0.0) return 0.0;
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 100000 && term > 1e-17 * sum; ++n) {
        term *= x / (a + n);
        sum += term;
    }
    return std::min(1.0, sum * std::exp(a * std::log(x) - x - std::lgamma(a)));
}

// The p-quantile of χ²/k with k degrees of freedom, by bisection of its CDF P(k/2, x/2): exact
// to 1e-10, where the usual cube-root approximation is 16 % off at the 2.5 % point for k = 3.
double chi2_per_dof_quantile(double p, double k) {
    double low = 0.0, high = k + 20.0 * std::sqrt(2.0 * k) + 20.0;
    while (high - low > 1e-10 * high) {
        const double mid = 0.5 * (low + high);
        (regularized_lower_gamma(0.5 * k, 0.5 * mid) < p ? low : high) = mid;
    }
    return 0.5 * (low + high) / k;
}

double standard_normal(SplitMix64& rng) {
    // Box–Muller; 1 − u keeps the logarithm finite.
    const double u = 1.0 - rng.uniform(), v = rng.uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

// A Gamma(shape, 1) draw (Marsaglia and Tsang, ACM TOMS 26, 363 (2000)); a shape below 1 is
// raised by one and scaled back by u^(1/shape).
double gamma_draw(double shape, SplitMix64& rng) {
    if (shape < 1.0)
        return gamma_draw(shape + 1.0, rng) * std::pow(1.0 - rng.uniform(), 1.0 / shape);
    const double d = shape - 1.0 / 3.0, c = 1.0 / std::sqrt(9.0 * d);
    for (;;) {
        double z, v;
        do {
            z = standard_normal(rng);
            v = 1.0 + c * z;
        } while (v <= 0.0);
        v = v * v * v;
        const double u = 1.0 - rng.uniform();
        if (std::log(u) < 0.5 * z * z + d - d * v + d * std::log(v)) return d * v;
    }
}

// The central 95 % of χ²/dof (unweighted mean, as combine_replicates) over draws of honest
// replicates: value i normal with standard deviation σ_i, its error σ_i √(χ²_ν/ν), ν = dof[i].
std::pair<double, double> honest_chi2_range(const std::vector<double>& sigma,
                                            const std::vector<double>& dof) {
    constexpr int draws = 20000;
    SplitMix64 rng(0x5EED'C412);  // fixed: the range is a property of σ and ν, not of a call
    const std::size_t n = sigma.size();
    std::vector<double> chi2(draws), x(n), e(n);
    for (double& c : chi2) {
        double mean = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            x[i] = sigma[i] * standard_normal(rng);
            e[i] = sigma[i] * std::sqrt(2.0 * gamma_draw(0.5 * dof[i], rng) / dof[i]);
            mean += x[i] / static_cast<double>(n);
        }
        c = 0.0;
        for (std::size_t i = 0; i < n; ++i)
            c += (x[i] - mean) * (x[i] - mean) / (e[i] * e[i]);
        c /= static_cast<double>(n - 1);
    }
    std::sort(chi2.begin(), chi2.end());
    return {chi2[static_cast<std::size_t>(0.025 * draws)],
            chi2[static_cast<std::size_t>(0.975 * draws)]};
}

}  // namespace

ReplicateEstimate combine_replicates(std::span<const double> values, std::span<const double> errors,
                                     std::span<const double> error_dof) {
    ReplicateEstimate r;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> x, e, nu;
    bool errors_known = true, dof_known = !error_dof.empty();
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) continue;
        x.push_back(values[i]);
        const double err = i < errors.size() ? errors[i] : nan;
        errors_known = errors_known && std::isfinite(err) && err > 0.0;
        e.push_back(err);
        const double dof = i < error_dof.size() ? error_dof[i] : nan;
        dof_known = dof_known && std::isfinite(dof) && dof > 0.0;
        nu.push_back(dof);
    }
    r.replicates = x.size();
    if (x.empty()) {
        r.mean = r.error = r.chi2_per_dof = r.own_error = nan;
        return r;
    }
    double own = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        r.mean += x[i] / static_cast<double>(x.size());
        own += e[i] * e[i];
    }
    r.own_error = errors_known ? std::sqrt(own) / static_cast<double>(x.size()) : nan;
    if (x.size() < 2) {
        r.error = r.chi2_per_dof = nan;
        return r;
    }
    const double dof = static_cast<double>(x.size() - 1);
    double var = 0.0, chi2 = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        var += (x[i] - r.mean) * (x[i] - r.mean) / dof;
        chi2 += errors_known ? (x[i] - r.mean) * (x[i] - r.mean) / (e[i] * e[i]) : 0.0;
    }
    r.error = std::sqrt(var / static_cast<double>(x.size()));
    r.chi2_per_dof = errors_known ? chi2 / dof : nan;
    if (errors_known && dof_known) {
        std::tie(r.chi2_low, r.chi2_high) = honest_chi2_range(e, nu);
    } else {
        r.chi2_low = chi2_per_dof_quantile(0.025, dof);
        r.chi2_high = chi2_per_dof_quantile(0.975, dof);
    }
    return r;
}

double slope_through_origin(std::span<const double> t, std::span<const double> y) {
    double ty = 0.0, tt = 0.0;
    for (std::size_t i = 0; i < t.size() && i < y.size(); ++i) {
        ty += t[i] * y[i];
        tt += t[i] * t[i];
    }
    return tt > 0.0 ? ty / tt : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace rodsea
