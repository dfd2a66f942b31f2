#include "rodsea/scenes/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/builder/placement.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

Scene single_body(const Species& species, double box_side, double tilt) {
    Scene scene;
    scene.params.box = {box_side, box_side};
    scene.params.species = {species};
    const Quat q = tipped_orientation(0.0, tilt);
    const double z = resting_height(species.shape, q, scene.params.drive);
    scene.bodies.add(0, {0.5 * box_side, 0.5 * box_side, z}, q);
    return scene;
}

Scene monolayer(const std::vector<Population>& populations, const Box& box, std::uint64_t seed) {
    Scene scene;
    scene.params.box = box;
    std::vector<long long> counts;
    for (const Population& p : populations) {
        scene.params.species.push_back(p.species);
        counts.push_back(p.count);
    }
    scene.bodies = build_initial_state(scene.params, counts, {}, seed);
    return scene;
}

Scene polar_in_apolar_mixture(double phi_polar, double apolar_length, double phi_apolar,
                              double box_side, std::uint64_t seed) {
    const Box box{box_side, box_side};
    Species polar = polar_rod_species();
    Species apolar = apolar_rod_species(apolar_length);
    const long long n_polar = count_for_area_fraction(phi_polar, box, polar.shape);
    const long long n_apolar = count_for_area_fraction(phi_apolar, box, apolar.shape);
    Scene scene = monolayer({{polar, n_polar}, {apolar, n_apolar}}, box, seed);
    scene.params.seed = seed;
    return scene;
}

}  // namespace rodsea
