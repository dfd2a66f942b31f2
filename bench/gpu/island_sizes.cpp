// How large the islands of contacts are (bodies linked by body–body contacts, a plate linking
// nothing): what decides how the GPU backend resolves impulses (one thread per island). The
// reference mixture (polar rods at φ_p = 0.05 in 2.5 mm apolar rods) at the area fractions given,
// in a 40 mm box, ε = 0.02: 4000 steps of settling, then 4000 steps measured.
//
//   rodsea_island_sizes 0.5 0.7 0.78        docs/performance.md, "Islands are small"
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numeric>
#include <vector>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

int main(int argc, char** argv) {
    for (int arg = 1; arg < argc; ++arg) {
        const double phi = std::atof(argv[arg]);
        rodsea::Scene scene = rodsea::polar_in_apolar_mixture(0.05, 2.5, phi, 40.0, 1);
        scene.params.noise_epsilon = 0.02;
        rodsea::Simulation sim(scene.params, scene.bodies);
        sim.run(4000);
        std::map<std::size_t, std::size_t> islands_of_size;  // contacts in an island → islands
        std::size_t contacts = 0;
        const int steps = 4000;
        for (int s = 0; s < steps; ++s) {
            sim.step();
            const std::vector<rodsea::Contact>& list = sim.contacts();
            std::vector<std::uint32_t> parent(sim.bodies().size());
            std::iota(parent.begin(), parent.end(), 0u);
            const auto root = [&parent](std::uint32_t b) {
                while (parent[b] != b)
                    b = parent[b] = parent[parent[b]];
                return b;
            };
            for (const rodsea::Contact& c : list)
                if (!c.with_plate()) {
                    const std::uint32_t a = root(c.a), b = root(c.b);
                    if (a != b) parent[std::max(a, b)] = std::min(a, b);
                }
            std::map<std::uint32_t, std::size_t> size;
            for (const rodsea::Contact& c : list)
                ++size[root(c.a)];
            for (const auto& [island, n] : size)
                ++islands_of_size[n];
            contacts += list.size();
        }
        std::size_t islands = 0;
        for (const auto& [n, count] : islands_of_size)
            islands += count;
        std::printf(
            "phi_a %.2f: %zu bodies, %.1f contacts per step, %.1f %% of islands of one "
            "contact, largest island %zu contacts\n",
            phi, sim.bodies().size(), static_cast<double>(contacts) / steps,
            100.0 * static_cast<double>(islands_of_size[1]) /
                static_cast<double>(std::max<std::size_t>(islands, 1)),
            islands_of_size.empty() ? 0 : islands_of_size.rbegin()->first);
    }
    return 0;
}
