#pragma once
// Time averages of correlated samples. Error bars come from the integrated autocorrelation time
// τ_int (Sokal's automatic window), so a series with long memory gets the wide error bar it
// deserves: error = sqrt(var · 2τ_int / n). The steady-state start follows Chodera (J. Chem.
// Theory Comput. 12, 1799 (2016)): the earliest start that maximises the number of
// statistically independent samples n_eff = (n − t0) / (2τ_int).
#include <cstddef>
#include <span>
#include <vector>

namespace rodsea {

struct Estimate {
    double mean = 0.0;
    double error = 0.0;    // one standard error of the mean; NaN when it cannot be estimated
    double tau_int = 0.5;  // integrated autocorrelation time, in samples (0.5: uncorrelated)
    double n_eff = 0.0;    // statistically independent samples, n / (2 τ_int)
    std::size_t samples = 0;
    bool from_blocks = false;  // error from the spread of time blocks, not from τ_int

    // Sokal's window needs a series many τ_int long; below 50 τ_int a non-zero error bar is an
    // underestimate (the window closes before the correlation has decayed).
    bool short_series() const {
        return !from_blocks && error > 0.0 && static_cast<double>(samples) < 50.0 * tau_int;
    }
};

// Sokal's windowed estimate: τ = 1/2 + Σ_{t=1..W} ρ(t) with the smallest W ≥ 5 τ(W). A constant
// series has τ = 1/2.
double integrated_autocorrelation_time(std::span<const double> x);

Estimate estimate_mean(std::span<const double> x);

// Mean of `full` with the error from the spread of independent block values (standard error of
// the block mean); for quantities that only exist as a whole-window average (fits, contours).
Estimate estimate_from_blocks(double full, std::span<const double> blocks);

// Index of the first steady sample of `x` (Chodera's rule over starts every n/50 samples, up to
// half the series, so that at least half of the data is always kept).
std::size_t steady_start(std::span<const double> x);

// The mean of independent replicates (runs that differ only in their seed) with the error from
// their spread, sd / √n: honest whatever the correlation times, because the runs are independent.
// chi2_per_dof = Σ (x_i − x̄)² / σ_i² / (n − 1) sets that spread against each replicate's own
// quoted error σ_i: about 1, within [chi2_low, chi2_high] (its central 95 % for honest Gaussian
// errors), when the single-run errors are honest; far above when they are too small.
// error_dof[i], when given for every replicate, is the degrees of freedom σ_i was itself estimated
// with (n_eff − 1). An error from few independent samples scatters, and its scatter inflates
// χ²/dof (to a mean of ν/(ν − 2) for equal errors of ν > 2 degrees of freedom), so the range is
// then drawn by a seeded Monte Carlo of honest replicates with those errors (the same on every
// call). Without it, the χ² law's: the errors taken as exact.
struct ReplicateEstimate {
    double mean = 0.0;
    double error = 0.0;  // NaN with fewer than two finite values
    std::size_t replicates = 0;
    double chi2_per_dof = 0.0;  // NaN without a finite positive σ_i for every value
    double chi2_low = 0.0, chi2_high = 0.0;
    // √(Σ σ_i²) / n: the error of the mean from the runs' own errors; NaN as chi2_per_dof.
    double own_error = 0.0;
};
ReplicateEstimate combine_replicates(std::span<const double> values, std::span<const double> errors,
                                     std::span<const double> error_dof = {});

// Slope D of y = D t through the origin, least squares.
double slope_through_origin(std::span<const double> t, std::span<const double> y);

}  // namespace rodsea
