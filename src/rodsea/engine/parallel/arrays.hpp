#pragma once
// What the data-parallel step's kernels read and write: raw pointers into one executor's memory
// (host vectors or device buffers), plain values, so that a kernel object is copied to a device
// as it is.
#include <cstdint>

#include "rodsea/engine/parallel/system_run.hpp"
#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/rigid_rotation.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/math/hostdevice.hpp"
#include "rodsea/math/mat3.hpp"
#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/quat.hpp"

namespace rodsea::parallel {

struct BodyArrays {
    const std::uint32_t* species = nullptr;
    Vec3* position = nullptr;  // mm, x and y wrapped into the box
    Quat* orientation = nullptr;
    Vec3* velocity = nullptr;  // mm/s
    Vec3* spin = nullptr;      // rad/s, world frame
    std::uint32_t count = 0;
};

// The SpeciesTable's arrays (of every system of an ensemble, one after another).
struct SpeciesArrays {
    const double* inverse_mass = nullptr;
    const Vec3* inverse_inertia = nullptr;
    const physics::Rotor* rotor = nullptr;
    const double* reach2 = nullptr;
    const int* sphere_axis = nullptr;
    const std::uint32_t* first_sphere = nullptr;
    const Vec3* sphere_offset = nullptr;
    const ContactCoefficients* plate = nullptr;
    // Body–body coefficients: each system's species × species block, row-major, one block after
    // another (an ensemble's systems never touch each other). Species a's row starts at
    // pair_row[a]; species b is column local_index[b] of its system's block.
    const ContactCoefficients* pair = nullptr;
    const std::uint32_t* pair_row = nullptr;
    const std::uint32_t* local_index = nullptr;
    const std::uint8_t* polar = nullptr;
    std::uint32_t count = 0;

    RODSEA_HD const ContactCoefficients& pair_coefficients(std::uint32_t a, std::uint32_t b) const {
        return pair[pair_row[a] + local_index[b]];
    }
};

// A body's fastest approach to each plate among the impulses it got from it this step (mm/s;
// 0: none): what a polar body's noise kicks scale with (docs/model.md §3).
using PlateHits = physics::PlateApproach;

// The end of a list of contacts.
inline constexpr std::uint32_t kNoContact = 0xffffffffu;

// Every sphere of every body, in body order (SphereView's layout).
struct SphereArrays {
    const std::uint32_t* body = nullptr;
    const double* radius = nullptr;  // mm
    Vec3* position = nullptr;        // mm, world, x and y not wrapped
    const std::uint32_t* first_of = nullptr;
    std::uint32_t count = 0;
};

// The cell grid: the box cut into nx × ny cells no narrower than the widest reach of the
// neighbour list (two of the largest radii and the skin), so that a sphere's neighbours lie in its
// own and the eight surrounding cells.
struct CellGrid {
    std::uint32_t nx = 1, ny = 1;
    double width_x = 0.0, width_y = 0.0;  // mm

    RODSEA_HD std::uint32_t cells() const { return nx * ny; }
    RODSEA_HD std::uint32_t column_of(double x, double lx) const {
        const auto c = static_cast<std::uint32_t>(PeriodicBox2D::wrap(x, lx) / width_x);
        return c < nx ? c : nx - 1;  // x just below lx may round to nx
    }
    RODSEA_HD std::uint32_t row_of(double y, double ly) const {
        const auto r = static_cast<std::uint32_t>(PeriodicBox2D::wrap(y, ly) / width_y);
        return r < ny ? r : ny - 1;
    }
};

// One system's grid; its cells are first_cell .. first_cell + grid.cells() − 1 of the cell list.
struct SystemGrid {
    CellGrid grid;
    std::uint32_t first_cell = 0;
};

// The cell list, built with the neighbour list: each cell's spheres, in no particular order, in
// `room` slots of its own, so that a sphere is binned with one atomic and nothing is sorted or
// scanned: cell c holds sphere[c * room .. c * room + min(count[c], room)). A cell given more
// than `room` spheres reports how many (RunStatus::needed_cell_room): the run is taken again
// with more room. The counts are cleared as each step begins (the last build has read them).
struct CellList {
    std::uint32_t* count = nullptr;
    std::uint32_t* sphere = nullptr;
    std::uint32_t room = 0;
    std::uint32_t cells = 0;

    RODSEA_HD std::uint32_t* slots(std::uint32_t cell) const {
        return sphere + std::uint64_t{cell} * room;
    }
    RODSEA_HD std::uint32_t held(std::uint32_t cell) const {
        return count[cell] < room ? count[cell] : room;
    }
};

// The Verlet list of the GPU backend: for each sphere i, the spheres j > i of other bodies of its
// system whose discs (spheres seen from above) were closer than r_i + r_j + skin when it was
// built, ascending: j = slot[k * stride + i] for k < count[i] (slot-major, so that a warp's
// spheres read one row together). A sphere with more than `capacity` such partners keeps its
// first `capacity` and reports how many it has (RunStatus::needed_slots): the run is taken again
// with more room.
struct NeighbourList {
    std::uint32_t* slot = nullptr;
    std::uint32_t* count = nullptr;
    std::uint32_t capacity = 0;
    std::uint32_t stride = 0;  // the number of spheres
    double skin = 0.0;         // mm
};

// The independent systems stepped together (an ensemble; a lone run is one system): each body's
// system, and each system's step, first body, grid, state of its run and the counts of its step.
// Bodies, spheres and contacts of a system are contiguous, in system order.
struct Systems {
    const StepContext* context = nullptr;  // the step being taken, per system
    const std::uint32_t* of_body = nullptr;
    const std::uint32_t* first_body = nullptr;
    const SystemGrid* grid = nullptr;
    const SystemRun* run = nullptr;
    StepCounts* counts = nullptr;
    std::uint32_t count = 0;

    RODSEA_HD std::uint32_t of_sphere(const SphereArrays& spheres, std::uint32_t s) const {
        return of_body[spheres.body[s]];
    }
    // A system that blew up earlier in this run takes no more steps in it.
    RODSEA_HD bool halted(std::uint32_t system) const { return run[system].halted != 0; }
};

}  // namespace rodsea::parallel
