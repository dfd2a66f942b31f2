#include "rodsea/builder/monte_carlo.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rodsea/builder/disc_grid.hpp"
#include "rodsea/math/periodic_box.hpp"

namespace rodsea {

namespace {

constexpr double kTargetAcceptance = 0.4;  // middle of the 30–50 % band
constexpr double kLowAcceptance = 0.3, kHighAcceptance = 0.5;

// Steps start small enough for the densest lattice (whose free room is a few µm) and reach any
// size within a dozen sweeps: each sweep scales them by acceptance / target, within [1/2, 3].
constexpr double kFirstTranslation = 0.02;  // mm
constexpr double kFirstRotation = 0.02;     // rad
constexpr double kSmallestStep = 1e-7;      // mm or rad: below this nothing moves anyway

struct Tally {
    std::uint64_t attempted = 0, accepted = 0;
};

void adapt(double& step, Tally& tally, double largest) {
    if (tally.attempted > 0) {
        const double rate =
            static_cast<double>(tally.accepted) / static_cast<double>(tally.attempted);
        if (rate < kLowAcceptance || rate > kHighAcceptance)
            step *= std::clamp(rate / kTargetAcceptance, 0.5, 3.0);
        step = std::clamp(step, kSmallestStep, largest);
    }
    tally = {};
}

double wrap_angle(double a) {
    if (a > std::numbers::pi) return a - 2.0 * std::numbers::pi;
    if (a <= -std::numbers::pi) return a + 2.0 * std::numbers::pi;
    return a;
}

}  // namespace

MonteCarloResult randomise(PlanarBodies& bodies, const std::vector<Footprint>& feet, const Box& box,
                           const MonteCarloOptions& options, SplitMix64& rng) {
    MonteCarloResult result;
    const size_t n_species = feet.size();
    result.translation_step.assign(n_species, kFirstTranslation);
    result.rotation_step.assign(n_species, kFirstRotation);
    if (bodies.size() == 0) return result;

    DiscGrid grid(bodies, feet, box, options.clearance);
    for (std::uint32_t b = 0; b < bodies.size(); ++b) {
        if (!grid.trial(b, bodies.x[b], bodies.y[b], bodies.angle[b]))
            throw std::logic_error("builder: body " + std::to_string(b) +
                                   " overlaps another before randomisation");
    }

    // A jump of half the box is already a uniform reinsertion.
    const double largest_jump = 0.5 * std::min(box.lx, box.ly);
    std::vector<Tally> moved(n_species), turned(n_species);
    for (int sweep = 0; sweep < options.sweeps; ++sweep) {
        for (std::uint32_t b = 0; b < bodies.size(); ++b) {
            const std::uint32_t s = bodies.species[b];
            double x = bodies.x[b], y = bodies.y[b], angle = bodies.angle[b];
            const bool turn = options.rotate && feet[s].rotatable && rng.uniform() < 0.5;
            Tally& tally = turn ? turned[s] : moved[s];
            if (turn) {
                angle = wrap_angle(angle + result.rotation_step[s] * rng.uniform(-1.0, 1.0));
            } else {
                const double step = result.translation_step[s];
                x = PeriodicBox2D::wrap(x + step * rng.uniform(-1.0, 1.0), box.lx);
                y = PeriodicBox2D::wrap(y + step * rng.uniform(-1.0, 1.0), box.ly);
            }
            ++tally.attempted;
            if (!grid.trial(b, x, y, angle)) continue;
            grid.commit(b);
            bodies.x[b] = x;
            bodies.y[b] = y;
            bodies.angle[b] = angle;
            ++tally.accepted;
        }
        for (size_t s = 0; s < n_species; ++s) {
            result.attempted += moved[s].attempted + turned[s].attempted;
            result.accepted += moved[s].accepted + turned[s].accepted;
            adapt(result.translation_step[s], moved[s], largest_jump);
            adapt(result.rotation_step[s], turned[s], std::numbers::pi);
        }
        ++result.sweeps;
    }
    return result;
}

}  // namespace rodsea
