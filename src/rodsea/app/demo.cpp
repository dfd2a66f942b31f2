#include "rodsea/app/demo.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <ostream>
#include <sstream>

#include "rodsea/analysis/order_parameters.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {

namespace {

// Writes through a temporary file and renames it into place, so a reader never sees half a file.
void write_atomically(const std::filesystem::path& path, const std::string& text) {
    const std::filesystem::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot write " + tmp.string());
        out << text;
        out.flush();
        if (!out) throw std::runtime_error("failed writing " + tmp.string());
    }
    std::filesystem::rename(tmp, path);
}

std::string bodies_csv(const Simulation& sim) {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "# final body state; lengths in mm, velocities in mm/s, spins in rad/s, theta in rad\n";
    s << "id,species,kind,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,theta\n";
    const BodyState& b = sim.bodies();
    for (size_t i = 0; i < b.size(); ++i) {
        const Species& sp = sim.parameters().species[b.species[i]];
        const Vec3 &x = b.position[i], &v = b.velocity[i], &w = b.spin[i];
        const Quat& q = b.orientation[i];
        s << i << ',' << sp.name << ',' << to_string(sp.kind) << ',' << x.x << ',' << x.y << ','
          << x.z << ',' << q.w << ',' << q.x << ',' << q.y << ',' << q.z << ',' << v.x << ',' << v.y
          << ',' << v.z << ',' << w.x << ',' << w.y << ',' << w.z << ',' << in_plane_angle(q)
          << '\n';
    }
    return s.str();
}

std::string shapes_csv(const EngineParameters& p) {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "# sphere offsets in the body frame (mm) and radii (mm); box " << p.box.lx << " x "
      << p.box.ly << " mm\n";
    s << "species,kind,sphere,ox,oy,oz,radius\n";
    for (const Species& sp : p.species)
        for (size_t k = 0; k < sp.shape.sphere_count(); ++k)
            s << sp.name << ',' << to_string(sp.kind) << ',' << k << ',' << sp.shape.offsets[k].x
              << ',' << sp.shape.offsets[k].y << ',' << sp.shape.offsets[k].z << ','
              << sp.shape.radii[k] << '\n';
    return s.str();
}

}  // namespace

int run_demo(const DemoOptions& o, std::ostream& log) {
    require_in_closed_range("--periods", o.drive_periods, 0.001, 1e7);
    require_positive("--box", o.box_side, "mm");
    require_non_negative("--epsilon", o.noise_epsilon, "1/mm");

    Scene scene =
        polar_in_apolar_mixture(o.phi_polar, o.apolar_length, o.phi_apolar, o.box_side, o.seed);
    scene.params.noise_epsilon = o.noise_epsilon;
    const double period = 2.0 * std::numbers::pi / scene.params.drive.angular_frequency;
    const auto steps =
        static_cast<std::uint64_t>(std::llround(o.drive_periods * period / scene.params.dt));
    Simulation sim(scene.params, scene.bodies);
    const EngineParameters& p = sim.parameters();

    std::filesystem::create_directories(o.out_dir);
    log << "rodsea demo: polar rods in apolar rods (l_a = " << o.apolar_length << " mm)\n"
        << "  box " << p.box.lx << " x " << p.box.ly << " mm, gap " << p.drive.gap << " mm, Gamma "
        << p.drive.gamma << ", A = " << p.drive.amplitude() * 1e3 << " um\n"
        << "  bodies " << sim.bodies().size() << ", spheres " << sim.spheres().size() << ", dt "
        << p.dt * 1e6 << " us, " << steps << " steps (" << o.drive_periods << " drive periods, "
        << static_cast<double>(steps) * p.dt << " s)\n"
        << "  output " << o.out_dir << "/{bodies,shapes,timeseries}.csv\n";

    std::ostringstream series;
    series << std::setprecision(10);
    series << "# time in s, kinetic energy in mass units mm^2/s^2\n"
           << "time,P_polar,S_apolar,kinetic_energy,max_overlap_fraction,unresolved_total,max_"
              "sweeps\n";
    const auto record = [&] {
        series << sim.time() << ',' << orientational_order(sim.bodies(), 0, 1) << ','
               << orientational_order(sim.bodies(), 1, 2) << ',' << sim.kinetic_energy() << ','
               << sim.last_step().max_overlap_fraction << ',' << sim.totals().unresolved << ','
               << sim.totals().max_sweeps << '\n';
    };
    record();
    const std::uint64_t per_period = std::max<std::uint64_t>(1, std::llround(period / p.dt));
    const auto start = std::chrono::steady_clock::now();
    int last_decile = 0;
    for (std::uint64_t done = 0; done < steps;) {
        const std::uint64_t chunk = std::min(per_period, steps - done);
        sim.run(chunk);
        done += chunk;
        record();
        const int decile = static_cast<int>(10 * done / steps);
        if (!o.quiet && decile > last_decile) {
            last_decile = decile;
            const double wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const auto done_d = static_cast<double>(done);
            log << "  " << std::setw(3) << decile * 10 << "%  t = " << std::fixed
                << std::setprecision(3) << sim.time() << " s  P = " << std::setprecision(3)
                << orientational_order(sim.bodies(), 0, 1) << "  " << std::setprecision(0)
                << done_d / wall << " steps/s  ETA " << std::setprecision(1)
                << wall * static_cast<double>(steps - done) / done_d << " s\n"
                << std::defaultfloat;
        }
    }
    const std::filesystem::path dir(o.out_dir);
    write_atomically(dir / "bodies.csv", bodies_csv(sim));
    write_atomically(dir / "shapes.csv", shapes_csv(p));
    write_atomically(dir / "timeseries.csv", series.str());

    const StageProfile& prof = sim.profile();
    log << std::setprecision(4) << "done: P = " << orientational_order(sim.bodies(), 0, 1)
        << ", largest overlap " << sim.totals().max_overlap_fraction * 100
        << " % of a radius, unresolved contacts " << sim.totals().unresolved
        << ", most sweeps in a step " << sim.totals().max_sweeps << "\n"
        << "time per stage (s): free flight " << prof.free_flight << ", spheres "
        << prof.sphere_update << ", contact search " << prof.contact_search << ", resolution "
        << prof.resolution << ", noise " << prof.noise << "\n";
    return 0;
}

}  // namespace rodsea
