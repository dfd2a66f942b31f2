#pragma once
// Text formats that VMD, OVITO and MDAnalysis read, one particle per sphere (docs/export.md):
// a LAMMPS custom dump and extended XYZ. Each sphere carries its radius, its body (molecule)
// id, its species and the body's orientation quaternion, so the viewers draw the true shapes.
// Bodies are kept whole: the centre is wrapped into the box, spheres may stick out of [0, L)
// by less than a body length.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rodsea/config/run_plan.hpp"
#include "rodsea/engine/body_state.hpp"

namespace rodsea {

// gsd: one particle per body, written by scripts/rodsea_gsd.py (gsd.hoomd); the others here.
enum class ExportFormat { lammps_dump, xyz, gsd };

// The names the command line accepts, in the order help texts list them.
const std::vector<std::string>& export_format_names();
const char* to_string(ExportFormat format);
std::optional<ExportFormat> parse_export_format(std::string_view name);

// What every frame of a run shares: the box, the plates' range and each species' spheres.
struct ExportScene {
    double lx = 0.0, ly = 0.0;      // periodic box, mm
    double z_lo = 0.0, z_hi = 0.0;  // the plates' whole travel, −A to w + A, mm
    double dt = 0.0;                // s per step (a dump's TIMESTEP × dt is the time)
    struct Species {
        std::string name;
        std::vector<Vec3> offsets;  // sphere centres in the body frame, mm
        std::vector<double> radii;  // mm
    };
    std::vector<Species> species;
};

ExportScene make_export_scene(const RunPlan& plan);

struct ExportOptions {
    ExportFormat format = ExportFormat::lammps_dump;
    bool velocities = false;  // add the body centre's velocity (mm/s) to every sphere
};

// Spheres in a frame: Σ over bodies of their species' sphere count. Throws FileError naming
// `source` when a body's species index is not one of the scene's species.
std::size_t export_sphere_count(const ExportScene& scene, const BodyState& bodies,
                                const std::string& source);

// Where sphere `offset` of a body at `centre` with orientation `q` (body → world, normalised
// by the caller) is: centre + q offset q*. Not wrapped.
Vec3 export_sphere_position(const Vec3& centre, const Quat& q, const Vec3& offset);

// Writes one frame (header and one line per sphere) to `out`. The caller checks the stream.
// `step` is the simulation step, `time` its time in s.
void write_export_frame(std::ostream& out, const ExportScene& scene, const ExportOptions& options,
                        const BodyState& bodies, std::int64_t step, double time);

// Bytes of one frame of `spheres` spheres, estimated from a line of typical width: for the plan
// and the free-space check, not exact (number widths vary).
double estimated_frame_bytes(const ExportScene& scene, const ExportOptions& options,
                             std::size_t spheres, std::size_t bodies);

}  // namespace rodsea
