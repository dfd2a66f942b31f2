#include "rodsea/analyze/band_observable.hpp"

#include <cmath>
#include <numbers>

namespace rodsea {

void BandObservable::compute(const FrameContext& context) {
    const GroupArrays& polar = context.group(BodyGroup::polar);
    const double axis = director_angle(polar.angle);
    const BandAmplitudes b = band_amplitudes(context.frame().box, polar.position, axis);
    times_.push_back(context.frame().time);
    steady_.push_back(context.steady() ? 1 : 0);
    axis_.push_back(axis);
    amplitudes_.push_back(b);
}

ObservableResults BandObservable::finish() {
    ObservableResults r;
    r.observable = name();
    const auto n = static_cast<double>(setup_.polar_count());
    // E|ρ_k| for N independent uniform positions: Re and Im of Σ exp(i k·r) / N are Gaussian
    // with variance 1 / 2N each for large N, so |ρ_k| is Rayleigh with mean √(π / 4N).
    const double random = std::sqrt(std::numbers::pi / (4.0 * n));
    r.parameters = {{"polar_rods", n, ""}};
    TableResult t{"bands",
                  "the polar rods' density modes |ρ_k| = |Σ exp(i k·r)| / N for k = 2π (m_x / "
                  "L_x, m_y / L_y), those most nearly along (transverse bands) and across "
                  "(longitudinal bands) their axis of motion, and where each of these two peaks "
                  "along its k (arg ρ_k / |k|, mm from the box's origin: a band's drift across "
                  "itself)",
                  {"time", "steady", "axis", "rho_1_0", "rho_0_1", "rho_1_1", "rho_1_m1",
                   "transverse", "longitudinal", "transverse_at", "longitudinal_at"},
                  {"s", "", "rad", "", "", "", "", "", "", "mm", "mm"},
                  {}};
    std::vector<double> transverse, longitudinal;
    for (std::size_t k = 0; k < times_.size(); ++k) {
        const BandAmplitudes& b = amplitudes_[k];
        transverse.push_back(b.transverse);
        longitudinal.push_back(b.longitudinal);
        t.rows.push_back({times_[k], static_cast<double>(steady_[k]), axis_[k], b.modes[0],
                          b.modes[1], b.modes[2], b.modes[3], b.transverse, b.longitudinal,
                          b.transverse_at, b.longitudinal_at});
    }
    r.scalars.push_back({"band_transverse", "",
                         "|ρ_k| of the longest density mode along the polar rods' axis of motion "
                         "(transverse bands), steady mean",
                         steady_estimate(transverse, steady_)});
    r.scalars.push_back({"band_longitudinal", "",
                         "|ρ_k| of the longest density mode across the polar rods' axis of "
                         "motion (longitudinal bands), steady mean",
                         steady_estimate(longitudinal, steady_)});
    r.scalars.push_back({"band_random", "",
                         "mean |ρ_k| of the same number of polar rods at random positions, "
                         "√(π / 4N)",
                         Estimate{random, std::nan(""), 0.5, 0.0, 0}});
    // bands.threshold (CHOICE): a band is there when its mode stands that many random means.
    const double least = floors_ * random;
    r.parameters.push_back({"threshold", floors_, ""});  // in random means
    r.parameters.push_back({"band_threshold", least, ""});
    add_band_motion(
        r, "transverse", "along the motion (transverse bands)", least,
        [](const BandAmplitudes& b) { return b.transverse; },
        [](const BandAmplitudes& b) { return b.transverse_at; },
        [](const BandAmplitudes& b) { return b.transverse_mode; });
    add_band_motion(
        r, "longitudinal", "across the motion (longitudinal bands)", least,
        [](const BandAmplitudes& b) { return b.longitudinal; },
        [](const BandAmplitudes& b) { return b.longitudinal_at; },
        [](const BandAmplitudes& b) { return b.longitudinal_mode; });
    r.tables.push_back(std::move(t));
    return r;
}

template <class Amplitude, class At, class Mode>
void BandObservable::add_band_motion(ObservableResults& r, const std::string& kind,
                                     const std::string& what, double least, Amplitude amplitude,
                                     At at, Mode mode) const {
    // The steady window is the run's last frames, so its frames are consecutive in time.
    std::vector<double> time, position, size, present;
    std::vector<std::size_t> modes;
    for (std::size_t k = 0; k < times_.size(); ++k) {
        if (!steady_[k]) continue;
        time.push_back(times_[k]);
        position.push_back(at(amplitudes_[k]));
        size.push_back(amplitude(amplitudes_[k]));
        modes.push_back(mode(amplitudes_[k]));
        present.push_back(size.back() >= least ? 1.0 : 0.0);
    }
    r.scalars.push_back(
        {"band_" + kind + "_present", "",
         "fraction of the steady frames whose mode " + what + " stands above band_threshold",
         estimate_mean(present)});
    const std::vector<double> v = band_velocities(setup_.box, time, position, size, modes, least);
    r.scalars.push_back(
        {"band_" + kind + "_drift", "mm/s",
         "velocity of the band " + what +
             " across itself, along the k of its mode (+x, +y, (+x+y)/√2 or (+x−y)/√2), mean over "
             "the steady frame pairs that both hold it above band_threshold",
         estimate_mean(v)});
}

}  // namespace rodsea
