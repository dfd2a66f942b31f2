#include "rodsea/scenes/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "rodsea/error.hpp"
#include "rodsea/random.hpp"

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

Scene row_packed_monolayer(const std::vector<Population>& populations, const Box& box,
                           std::uint64_t seed) {
    constexpr double kMinGap = 0.01;  // mm between neighbours, so that nothing starts in contact
    Scene scene;
    scene.params.box = box;

    struct Row {
        size_t species;
        long long count;
        double order;  // where the row goes in the interleaved sequence, in (0, 1)
    };
    std::vector<Row> rows;
    double height = 0.0;
    for (size_t s = 0; s < populations.size(); ++s) {
        const Population& pop = populations[s];
        scene.params.species.push_back(pop.species);
        if (pop.count <= 0) continue;
        const Shape& shape = pop.species.shape;
        const long long per_row =
            static_cast<long long>(std::floor(box.lx / (shape.extent + kMinGap)));
        if (per_row < 1) {
            throw InvalidParameter("box.lx", format_number(box.lx) + " mm",
                                   ">= " + format_number(shape.extent + kMinGap) + " mm",
                                   "a " + pop.species.name + " must fit along a row");
        }
        const long long n_rows = (pop.count + per_row - 1) / per_row;
        for (long long r = 0; r < n_rows; ++r) {
            const long long in_row = std::min(per_row, pop.count - r * per_row);
            rows.push_back(
                {s, in_row, (static_cast<double>(r) + 0.5) / static_cast<double>(n_rows)});
        }
        height += static_cast<double>(n_rows) * (2.0 * shape.max_radius + kMinGap);
    }
    if (height > box.ly) {
        throw InvalidParameter("area_fraction", "too high for a row packing",
                               "rows of total width <= box.ly = " + format_number(box.ly) + " mm",
                               "these bodies need " + format_number(height) + " mm of rows");
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [](const Row& a, const Row& b) { return a.order < b.order; });

    SplitMix64 rng(seed);
    const double spare_y = (box.ly - height) / static_cast<double>(rows.size());
    double y = 0.0;
    for (const Row& row : rows) {
        const Species& sp = scene.params.species[row.species];
        const double width = 2.0 * sp.shape.max_radius + kMinGap + spare_y;
        const double pitch = box.lx / static_cast<double>(row.count);
        const double x0 = rng.uniform(0.0, pitch);  // rows are not in register
        for (long long i = 0; i < row.count; ++i) {
            const Quat q = flat_orientation(rng.uniform() < 0.5 ? 0.0 : std::numbers::pi);
            const double z = resting_height(sp.shape, q, scene.params.drive);
            // Lattice sites hold geometric centres: a polar rod's centre of mass is off-centre.
            const Vec3 site{x0 + pitch * static_cast<double>(i), y + 0.5 * width, z};
            const Vec3 com_from_centre =
                rotate(q, rotate(sp.shape.definition_to_body, sp.shape.com_in_definition_frame));
            const Vec3 v{rng.uniform(-kStartSpeed, kStartSpeed),
                         rng.uniform(-kStartSpeed, kStartSpeed), 0.0};
            const Vec3 w{rng.uniform(-kStartSpin, kStartSpin), rng.uniform(-kStartSpin, kStartSpin),
                         rng.uniform(-kStartSpin, kStartSpin)};
            scene.bodies.add(static_cast<std::uint32_t>(row.species),
                             {site.x + com_from_centre.x, site.y + com_from_centre.y, z}, q, v, w);
        }
        y += width;
    }
    return scene;
}

Scene polar_in_apolar_mixture(double phi_polar, double apolar_length, double phi_apolar,
                              double box_side, std::uint64_t seed) {
    const Box box{box_side, box_side};
    Species polar = polar_rod_species();
    Species apolar = apolar_rod_species(apolar_length);
    const long long n_polar = count_for_area_fraction(phi_polar, box, polar.shape);
    const long long n_apolar = count_for_area_fraction(phi_apolar, box, apolar.shape);
    Scene scene = row_packed_monolayer({{polar, n_polar}, {apolar, n_apolar}}, box, seed);
    scene.params.seed = seed;
    return scene;
}

}  // namespace rodsea
