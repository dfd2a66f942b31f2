#pragma once
// Bands of polar rods as the longest-wavelength modes of their density: ρ_k = (1/N) Σ_j
// exp(i k·r_j) over the N rods for the wave-vectors of the periodic box with the fewest
// wavelengths across it, k = 2π (m_x / L_x, m_y / L_y) for (m_x, m_y) = (1, 0), (0, 1), (1, 1),
// (1, −1). |ρ_k| is 0 for a uniform lattice, |sin(k w / 2) / (k w / 2)| for a uniform band of
// width w spanning the box across k, and √(π / 4N) on average for N random positions: a band
// that spans the box shows up as one large |ρ_k|. Relative to the rods' axis of motion the paper
// tells two kinds apart (its Fig. 4): transverse bands, wider across the motion than along it, so
// that the density varies along the motion (k ∥ axis); longitudinal bands, along the motion, so
// that it varies across it (k ⊥ axis).
#include <array>
#include <complex>
#include <span>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct DensityMode {
    int mx = 0, my = 0;  // wavelengths across the box in x and in y
};

// (1, 0), (0, 1), (1, 1), (1, −1): the longest wavelengths a periodic box holds along x, y and
// its two diagonals.
inline constexpr std::array<DensityMode, 4> kLongestModes{
    {DensityMode{1, 0}, DensityMode{0, 1}, DensityMode{1, 1}, DensityMode{1, -1}}};

// ρ_k of the points for the mode's wave-vector; NaN for no points.
std::complex<double> density_mode(const PeriodicBox2D& box, std::span<const Vec3> points,
                                  DensityMode mode);

// |ρ_k|, in [0, 1]; NaN for no points.
double density_mode_amplitude(const PeriodicBox2D& box, std::span<const Vec3> points,
                              DensityMode mode);

// Where the mode's density peaks, along its k (mm from the box's origin, in [0, 2π / |k|)): for
// a band, its centre line across its width; its change over time is the band's drift across
// itself. arg(ρ_k) / |k|, NaN for no points.
double density_mode_position(const PeriodicBox2D& box, std::complex<double> rho, DensityMode mode);

// The angle (rad, in [0, π)) of the axis that rods with in-plane angles θ point along, either
// way: half the angle of ⟨(cos 2θ, sin 2θ)⟩. NaN when that mean is zero to rounding (S below
// 1e-12: no axis) or there are no angles.
double director_angle(std::span<const double> theta);

struct BandAmplitudes {
    std::array<double, kLongestModes.size()> modes{};  // |ρ_k| of each of kLongestModes
    // |ρ_k| of the mode whose k is most nearly along the axis (transverse bands) and of the one
    // most nearly across it (longitudinal bands); NaN without an axis.
    double transverse = 0.0, longitudinal = 0.0;
    // Where those two modes peak along their k (density_mode_position), mm; NaN without an axis.
    double transverse_at = 0.0, longitudinal_at = 0.0;
    // Which of kLongestModes they are.
    std::size_t transverse_mode = 0, longitudinal_mode = 0;
};

// The modes of `points` and their split relative to the axis at angle `axis` (rad, mod π).
BandAmplitudes band_amplitudes(const PeriodicBox2D& box, std::span<const Vec3> points, double axis);

// A band's velocity across itself between consecutive frames, mm/s along the k of its mode: for
// each pair of frames k − 1, k that both hold it (amplitude[k] >= least) in the same mode of
// kLongestModes, (at[k] − at[k − 1]) / (time[k] − time[k − 1]) with the displacement taken into
// (−λ/2, λ/2] (λ = 2π / |k|: the phase is known modulo a wavelength, and a band moves far less
// than half a box between frames). In time order; none where no two consecutive frames qualify.
std::vector<double> band_velocities(const PeriodicBox2D& box, std::span<const double> time,
                                    std::span<const double> at, std::span<const double> amplitude,
                                    std::span<const std::size_t> mode, double least);

}  // namespace rodsea
