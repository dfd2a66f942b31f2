#include "rodsea/analysis/density_modes.hpp"

#include <cmath>
#include <numbers>

namespace rodsea {

namespace {

Vec3 wave_vector(const PeriodicBox2D& box, DensityMode mode) {
    const double two_pi = 2.0 * std::numbers::pi;
    return {two_pi * mode.mx / box.lx, two_pi * mode.my / box.ly, 0.0};
}

}  // namespace

std::complex<double> density_mode(const PeriodicBox2D& box, std::span<const Vec3> points,
                                  DensityMode mode) {
    if (points.empty()) return {std::nan(""), std::nan("")};
    const Vec3 k = wave_vector(box, mode);
    double re = 0.0, im = 0.0;
    for (const Vec3& p : points) {
        // k turns a whole number of times per box side: any periodic image gives the same ρ_k.
        const double phase = k.x * p.x + k.y * p.y;
        re += std::cos(phase);
        im += std::sin(phase);
    }
    const auto n = static_cast<double>(points.size());
    return {re / n, im / n};
}

double density_mode_amplitude(const PeriodicBox2D& box, std::span<const Vec3> points,
                              DensityMode mode) {
    return std::abs(density_mode(box, points, mode));
}

double density_mode_position(const PeriodicBox2D& box, std::complex<double> rho, DensityMode mode) {
    const Vec3 k = wave_vector(box, mode);
    const double length = std::hypot(k.x, k.y), wavelength = 2.0 * std::numbers::pi / length;
    const double at = std::arg(rho) / length;  // (−λ/2, λ/2]
    return at < 0.0 ? at + wavelength : at;
}

double director_angle(std::span<const double> theta) {
    double c = 0.0, s = 0.0;
    for (const double t : theta) {
        c += std::cos(2.0 * t);
        s += std::sin(2.0 * t);
    }
    // S below 1e-12 is rounding (sin 2θ of θ = π/2 is 1e-16, not 0): no axis.
    if (std::hypot(c, s) <= 1e-12 * static_cast<double>(theta.size())) return std::nan("");
    const double angle = 0.5 * std::atan2(s, c);  // (−π/2, π/2]
    return angle < 0.0 ? angle + std::numbers::pi : angle;
}

BandAmplitudes band_amplitudes(const PeriodicBox2D& box, std::span<const Vec3> points,
                               double axis) {
    BandAmplitudes b;
    std::array<std::complex<double>, kLongestModes.size()> rho;
    for (std::size_t m = 0; m < kLongestModes.size(); ++m) {
        rho[m] = density_mode(box, points, kLongestModes[m]);
        b.modes[m] = std::abs(rho[m]);
    }
    if (!std::isfinite(axis)) {
        b.transverse = b.longitudinal = b.transverse_at = b.longitudinal_at = std::nan("");
        return b;
    }
    // |cos| of the angle between each k and the axis; the first mode wins a tie.
    const Vec3 along{std::cos(axis), std::sin(axis), 0.0};
    std::size_t most_along = 0, most_across = 0;
    double best_along = -1.0, best_across = 2.0;
    for (std::size_t m = 0; m < kLongestModes.size(); ++m) {
        const Vec3 k = wave_vector(box, kLongestModes[m]);
        const double c = std::abs(k.x * along.x + k.y * along.y) / std::hypot(k.x, k.y);
        if (c > best_along) best_along = c, most_along = m;
        if (c < best_across) best_across = c, most_across = m;
    }
    b.transverse = b.modes[most_along];
    b.longitudinal = b.modes[most_across];
    b.transverse_at = density_mode_position(box, rho[most_along], kLongestModes[most_along]);
    b.longitudinal_at = density_mode_position(box, rho[most_across], kLongestModes[most_across]);
    b.transverse_mode = most_along;
    b.longitudinal_mode = most_across;
    return b;
}

std::vector<double> band_velocities(const PeriodicBox2D& box, std::span<const double> time,
                                    std::span<const double> at, std::span<const double> amplitude,
                                    std::span<const std::size_t> mode, double least) {
    std::vector<double> velocities;
    for (std::size_t k = 1; k < time.size(); ++k) {
        // NaN amplitudes (no axis) fail the comparison and are left out.
        if (!(amplitude[k - 1] >= least && amplitude[k] >= least) || mode[k] != mode[k - 1])
            continue;
        const Vec3 q = wave_vector(box, kLongestModes[mode[k]]);
        const double wavelength = 2.0 * std::numbers::pi / std::hypot(q.x, q.y);
        double step = at[k] - at[k - 1];
        step -= wavelength * std::round(step / wavelength);
        velocities.push_back(step / (time[k] - time[k - 1]));
    }
    return velocities;
}

}  // namespace rodsea
