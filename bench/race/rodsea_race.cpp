// rodsea's side of the LAMMPS race (bench/race/race.sh runs both): the race system for a warm-up
// and then a timed stretch of simulated time, on a given number of threads. Prints one summary
// line per run that race.sh parses.
//
//   rodsea_race [--threads N] [--dt SECONDS] [--warmup SECONDS] [--time SECONDS]
//               [--cells NX NY] [--seed N] [--shuffle] [--write-lammps FILE]
//
// --shuffle starts with the rods in random order in memory, as they end up after a long run in
// which they wander far: what spatial order of the bodies is worth.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <random>
#include <string>

#include "race_system.hpp"
#include "rodsea/engine/simulation.hpp"

namespace {

// Peak resident memory of this process (bytes), from /proc; 0 where there is none.
double peak_resident_bytes() {
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmHWM:") {
            double kib = 0.0;
            status >> kib;
            return 1024.0 * kib;
        }
        status.ignore(1 << 12, '\n');
    }
    return 0.0;
}

// The bodies in a random order (Fisher–Yates, seeded).
rodsea::BodyState shuffled(const rodsea::BodyState& in, std::uint64_t seed) {
    std::vector<size_t> order(in.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::mt19937_64 random(seed);
    std::shuffle(order.begin(), order.end(), random);
    rodsea::BodyState out;
    for (const size_t i : order)
        out.add(in.species[i], in.position[i], in.orientation[i], in.velocity[i], in.spin[i]);
    return out;
}

struct Options {
    int threads = 1;
    double dt = 1.25e-6;   // s
    double warmup = 0.01;  // s
    double time = 0.05;    // s
    int cells_x = 25, cells_y = 80;
    std::uint64_t seed = 1;
    std::string lammps_data;
    bool shuffle = false;
};

[[noreturn]] void usage(const std::string& why) {
    std::fprintf(stderr,
                 "rodsea_race: %s\nusage: rodsea_race [--threads N] [--dt SECONDS] "
                 "[--warmup SECONDS] [--time SECONDS] [--cells NX NY] [--seed N] [--shuffle] "
                 "[--write-lammps FILE]\n",
                 why.c_str());
    std::exit(2);
}

double positive(const char* text, const std::string& flag) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0' || !(v > 0.0) || !std::isfinite(v))
        usage(flag + " wants a positive number, not '" + text + "'");
    return v;
}

int whole(const char* text, const std::string& flag) {
    const double v = positive(text, flag);
    if (v != std::floor(v) || v > 1e6)
        usage(flag + " wants a whole number >= 1, not '" + text + "'");
    return static_cast<int>(v);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        const auto value = [&]() -> const char* {
            if (i + 1 >= argc) usage(flag + " needs a value");
            return argv[++i];
        };
        if (flag == "--threads")
            o.threads = whole(value(), flag);
        else if (flag == "--dt")
            o.dt = positive(value(), flag);
        else if (flag == "--warmup")
            o.warmup = positive(value(), flag);
        else if (flag == "--time")
            o.time = positive(value(), flag);
        else if (flag == "--cells") {
            o.cells_x = whole(value(), flag);
            o.cells_y = whole(value(), flag);
        } else if (flag == "--seed")
            o.seed = static_cast<std::uint64_t>(whole(value(), flag));
        else if (flag == "--shuffle")
            o.shuffle = true;
        else if (flag == "--write-lammps")
            o.lammps_data = value();
        else
            usage("unknown flag '" + flag + "'");
    }
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    try {
        rodsea::Scene scene = rodsea::race::race_scene(o.cells_x, o.cells_y, o.seed);
        if (!o.lammps_data.empty()) {
            rodsea::race::write_lammps_data(scene, o.lammps_data);
            std::printf("wrote %s: %zu rods\n", o.lammps_data.c_str(), scene.bodies.size());
            return 0;
        }
        if (o.shuffle) scene.bodies = shuffled(scene.bodies, o.seed);
        scene.params.dt = o.dt;
        rodsea::Simulation sim(scene.params, scene.bodies, {.threads = o.threads});
        const auto warmup_steps = static_cast<std::uint64_t>(std::llround(o.warmup / o.dt));
        const auto steps = static_cast<std::uint64_t>(std::llround(o.time / o.dt));
        sim.run(warmup_steps);
        const std::uint64_t builds_before = sim.pair_list_builds();
        // What a converged step must not change (converge.sh compares time steps): the collision
        // rates and the mean squared velocity in the plane and along z. Reading them costs
        // nothing next to a step.
        std::uint64_t body_collisions = 0, plate_collisions = 0;
        double in_plane = 0.0, vertical = 0.0;  // <v_xy²>, <v_z²> summed over samples (mm²/s²)
        int samples = 0;
        const auto sample_every = std::max<std::uint64_t>(1, steps / 100);
        const auto start = std::chrono::steady_clock::now();
        for (std::uint64_t i = 0; i < steps; ++i) {
            sim.step();
            body_collisions += sim.last_step().body_collisions;
            plate_collisions += sim.last_step().plate_collisions;
            if (i % sample_every == 0) {
                const rodsea::BodyState& b = sim.bodies();
                double xy = 0.0, z = 0.0;
                for (const rodsea::Vec3& v : b.velocity) {
                    xy += v.x * v.x + v.y * v.y;
                    z += v.z * v.z;
                }
                in_plane += xy / static_cast<double>(b.size());
                vertical += z / static_cast<double>(b.size());
                ++samples;
            }
        }
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double spheres = static_cast<double>(sim.spheres().size());
        const auto timed = static_cast<double>(steps);
        const double per_body_second = 1.0 / (static_cast<double>(sim.bodies().size()) * o.time);
        std::printf(
            "rodsea threads=%d bodies=%zu spheres=%.0f dt=%g steps=%llu wall=%.3f "
            "steps_per_s=%.1f sphere_steps_per_s=%.4g sim_s_per_wall_s=%.6g unresolved=%llu "
            "max_overlap=%.4f body_collision_rate=%.2f plate_collision_rate=%.2f "
            "in_plane_speed2=%.3f vertical_speed2=%.3f pair_list_builds=%llu peak_rss_mb=%.1f\n",
            o.threads, sim.bodies().size(), spheres, o.dt, static_cast<unsigned long long>(steps),
            wall, timed / wall, timed * spheres / wall, o.time / wall,
            static_cast<unsigned long long>(sim.totals().unresolved),
            sim.totals().max_overlap_fraction,
            static_cast<double>(body_collisions) * per_body_second,
            static_cast<double>(plate_collisions) * per_body_second, in_plane / samples,
            vertical / samples,
            static_cast<unsigned long long>(sim.pair_list_builds() - builds_before),
            peak_resident_bytes() / 1048576.0);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rodsea_race: %s\n", e.what());
        return 1;
    }
    return 0;
}
