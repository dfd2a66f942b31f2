// A dense monolayer of apolar rods (φ_a ≈ 0.6, ℓ_a = 2.5 mm) on the vibrated cell for 100 drive
// periods: every body stays between the plates, overlaps stay small, every contact resolves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "each_backend.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

class DenseMonolayer : public testing::EachBackend {};

// 100 drive periods; 20 on the GPU's algorithm run by the host, which is ~20× slower than the CPU
// backend (it is a check of the device's algorithm, not a way to run).
TEST_P(DenseMonolayer, StaysInTheGapWithSmallOverlapsForManyPeriods) {
    const Box box{15.3, 15.3};  // 6 rods of 2.5 mm per row, 2× the rod length
    const Species rods = apolar_rod_species(2.5);
    const long long n = count_for_area_fraction(0.6, box, rods.shape);
    Scene scene = monolayer({{rods, n}}, box, 17);
    Simulation sim(scene.params, scene.bodies, options());
    const double period = 2 * std::numbers::pi / scene.params.drive.angular_frequency;
    const auto steps_per_period =
        static_cast<std::uint64_t>(std::llround(period / scene.params.dt));

    double worst_escape = 0.0;  // how far any sphere surface got beyond a plate (mm)
    const int periods = GetParam() == BackendKind::gpu_on_host ? 20 : 100;
    for (int p = 0; p < periods; ++p) {
        for (std::uint64_t s = 0; s < steps_per_period; ++s) {
            sim.step();
            const physics::PlateState plates = sim.plates();
            const SphereView spheres = sim.spheres();
            for (size_t k = 0; k < spheres.size(); ++k) {
                const double z = spheres.position[k].z, r = spheres.radius[k];
                worst_escape =
                    std::max({worst_escape, plates.base_z - (z - r), (z + r) - plates.lid_z});
            }
        }
    }
    const RunTotals& t = sim.totals();
    std::printf(
        "[ measured ] %lld rods, largest overlap %.4f of the smaller radius, "
        "deepest plate penetration %.2e mm, most sweeps %d, impulses %llu\n",
        n, t.max_overlap_fraction, worst_escape, t.max_sweeps,
        static_cast<unsigned long long>(t.impulses));
    EXPECT_EQ(t.unresolved, 0u);
    // Bound: a contact overlaps by at most what the bodies' relative approach speed carries
    // them in one step before it is resolved. Relative speeds stay below ~4 AΩ ≈ 220 mm/s
    // (a body thrown by one plate meeting the other), i.e. 1.1 µm per 5 µs step, 0.55 % of the
    // smallest (0.2 mm) radius; allow ten such steps of accumulation in a jammed cluster.
    EXPECT_LT(t.max_overlap_fraction, 0.055);
    // No sphere crosses a plate by more than that same bound in absolute terms: no escape.
    EXPECT_LT(worst_escape, 0.055 * 0.2);
}

RODSEA_ON_EACH_STEP(DenseMonolayer);

}  // namespace
}  // namespace rodsea
