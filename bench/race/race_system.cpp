#include "race_system.hpp"

#include <cmath>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/random.hpp"
#include "rodsea/shape/shape.hpp"

namespace rodsea::race {

namespace {

double gaussian(SplitMix64& rng) {  // Box–Muller, one of the pair
    const double u = 1.0 - rng.uniform(), v = rng.uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

Species race_rod() {
    SphereList spheres;
    const double r = 0.5 * kSphereDiameter;
    const double spacing = (kRodLength - kSphereDiameter) / (kSpheresPerRod - 1);
    for (int k = 0; k < kSpheresPerRod; ++k)
        spheres.push_back({{(k - 0.5 * (kSpheresPerRod - 1)) * spacing, 0.0, 0.0}, r});
    Species rod;
    rod.name = "rod";
    rod.kind = BodyKind::apolar_rod;  // no noise kicks, as in the peer
    rod.shape = make_shape(spheres, 1.0, "race rod");
    rod.plate = {0.05, 0.3};
    return rod;
}

}  // namespace

Scene race_scene(int cells_x, int cells_y, std::uint64_t seed) {
    Scene scene;
    EngineParameters& p = scene.params;
    p.box = {cells_x * kCellX, cells_y * kCellY};
    p.drive.gamma = 7.0;
    p.drive.angular_frequency = 400.0 * std::numbers::pi;
    p.drive.gap = kGap;
    p.species = {race_rod()};
    p.body_body = {0.05, 0.3};
    p.noise_epsilon = 0.0;
    p.seed = seed;
    SplitMix64 rng(seed);
    const double mid_gap = physics::plate_state(p.drive.motion(), 0.0).base_z + 0.5 * kGap;
    for (int i = 0; i < cells_x; ++i) {
        for (int j = 0; j < cells_y; ++j) {
            const double deg = std::numbers::pi / 180.0;
            const double heading =
                rng.uniform(-5.0, 5.0) * deg + (rng.uniform() < 0.5 ? std::numbers::pi : 0.0);
            const double tilt = rng.uniform(-4.0, 4.0) * deg;
            const Quat q = flat_orientation(heading) * Quat::from_axis_angle({0, 1, 0}, -tilt);
            const Vec3 v{50.0 * gaussian(rng), 50.0 * gaussian(rng), 20.0 * gaussian(rng)};
            scene.bodies.add(0, {(i + 0.5) * kCellX, (j + 0.5) * kCellY, mid_gap}, q, v, {});
        }
    }
    return scene;
}

void write_lammps_data(const Scene& scene, const std::string& path) {
    const EngineParameters& p = scene.params;
    const Shape& shape = p.species[0].shape;
    const BodyState& b = scene.bodies;
    const double m = 1e-3;  // mm → m
    const physics::PlateState plates = physics::plate_state(p.drive.motion(), 0.0);
    // LAMMPS' plates start at z = 0 and rise to 2A (lo + A(1 − cos ωt)); rodsea's base starts at
    // A and falls: shift so that both start at the base.
    const double shift = -plates.base_z;
    const size_t atoms = b.size() * shape.sphere_count();
    replace_file_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp);
        out.precision(10);
        out << "rodsea race: " << b.size() << " rods x " << shape.sphere_count() << " spheres\n\n"
            << atoms << " atoms\n1 atom types\n\n"
            << "0 " << p.box.lx * m << " xlo xhi\n0 " << p.box.ly * m << " ylo yhi\n"
            << -0.3 * m << " " << (p.drive.gap + 0.3) * m << " zlo zhi\n\nAtoms # sphere\n\n";
        size_t id = 0;
        for (size_t r = 0; r < b.size(); ++r) {
            for (size_t s = 0; s < shape.sphere_count(); ++s) {
                const Vec3 x = b.position[r] + rotate(b.orientation[r], shape.offsets[s]);
                out << ++id << " 1 " << 2.0 * shape.radii[s] * m << " " << kDensity << " "
                    << x.x * m << " " << x.y * m << " " << (x.z + shift) * m << "\n";
            }
        }
        out << "\nVelocities\n\n";
        id = 0;
        for (size_t r = 0; r < b.size(); ++r) {
            const Vec3& v = b.velocity[r];
            for (size_t s = 0; s < shape.sphere_count(); ++s)
                out << ++id << " " << v.x * m << " " << v.y * m << " " << v.z * m << " 0 0 0\n";
        }
        out << "\nMolecules\n\n";
        id = 0;
        for (size_t r = 0; r < b.size(); ++r)
            for (size_t s = 0; s < shape.sphere_count(); ++s)
                out << ++id << " " << r + 1 << "\n";
        out.close();
        if (!out) throw std::runtime_error("could not write " + tmp.string());
    });
}

}  // namespace rodsea::race
