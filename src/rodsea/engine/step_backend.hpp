#pragma once
// The seam between the step's script and its executor. Simulation builds a StepContext each step
// and hands it to its backend, which owns the state and the scratch of every stage and runs
// free flight → sphere update → contact search → impulse resolution and plate projection →
// noise. The CPU backend (engine/cpu/) runs the stages as OpenMP loops; the GPU backend
// (engine/parallel/ run by engine/cuda/) as kernels; both over the same per-element physics
// (engine/physics/). backend_factory.hpp picks one.
//
// Determinism contract: a backend gives the same trajectory, bit for bit, for the same state,
// parameters and options. The CPU backend gives the same bits on any number of threads; the
// GPU backend on one device with one build.
#include <cstdint>
#include <span>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/step_context.hpp"
#include "rodsea/math/hostdevice.hpp"

namespace rodsea {

struct EngineParameters;

struct StepStatistics {
    std::size_t body_contacts = 0;
    std::size_t plate_contacts = 0;
    int sweeps = 0;
    std::size_t impulses = 0;
    std::size_t body_collisions = 0;   // impulses at approach speeds above kCollisionSpeed
    std::size_t plate_collisions = 0;  // the same with a plate
    // Contacts still approaching after the sweep cap, and contacts deeper than
    // kGrossOverlapFraction (state_check.hpp): impulses cannot undo an overlap that deep.
    std::size_t unresolved = 0;
    std::size_t noise_kicks = 0;
    double max_overlap_fraction = 0.0;  // largest overlap / smaller radius found this step
    double max_planar_speed = 0.0;      // mm/s, a bound on every sphere's in-plane speed
    // Bodies flown, placed and searched in this step: all of them, but for the coasting step
    // (the bodies awake), and 0 from a backend that does not count them (the GPU's).
    std::size_t bodies_flown = 0;
};

// Several steps together (a run of them, or every step since the start): the counts summed, the
// extremes at their largest.
struct StepTally {
    std::uint64_t steps = 0;
    std::uint64_t impulses = 0;
    std::uint64_t body_collisions = 0;
    std::uint64_t plate_collisions = 0;
    std::uint64_t unresolved = 0;
    std::uint64_t noise_kicks = 0;
    std::uint64_t body_steps = 0;  // bodies_flown, summed
    int max_sweeps = 0;
    double max_overlap_fraction = 0.0;

    // Written out rather than with std::max: a device runs it too.
    RODSEA_HD void add(const StepStatistics& step) {
        ++steps;
        impulses += step.impulses;
        body_collisions += step.body_collisions;
        plate_collisions += step.plate_collisions;
        unresolved += step.unresolved;
        noise_kicks += step.noise_kicks;
        body_steps += step.bodies_flown;
        if (step.sweeps > max_sweeps) max_sweeps = step.sweeps;
        if (step.max_overlap_fraction > max_overlap_fraction)
            max_overlap_fraction = step.max_overlap_fraction;
    }
    void add(const StepTally& other);
};

// What one step may show before the run counts as blown up (state_check.hpp says why these and
// describes a crossing; BlowUpBounds::of makes them). Here so that a device can test them.
struct BlowUpBounds {
    double planar_speed = 0.0;    // mm/s, planar_speed_bound()
    double overlap_fraction = 0;  // of the smaller radius (kGrossOverlapFraction)
    std::size_t unresolved = 0;   // 1 % of the bodies, at least 10 (a healthy run leaves none)

    static BlowUpBounds of(const EngineParameters& params, std::size_t bodies);

    // Values that are not finite cross them.
    RODSEA_HD bool crossed_by(const StepStatistics& step) const {
        return !(step.max_planar_speed <= planar_speed) ||
               !(step.max_overlap_fraction <= overlap_fraction) || step.unresolved > unresolved;
    }
};

// What a run of steps came to.
struct StepsDone {
    std::uint64_t steps = 0;  // taken: all asked for, or up to and including one that blew up
    bool blew_up = false;     // the last step taken crossed the bounds
    StepStatistics last;      // of the last step taken
    StepTally tally;          // of every step taken
};

// Wall-clock seconds spent in each stage.
struct StageProfile {
    double free_flight = 0.0;
    double sphere_update = 0.0;
    double contact_search = 0.0;
    double resolution = 0.0;  // impulses and the projection out of the plates
    double noise = 0.0;
    // Steps timed as a whole: a device's runs of steps, whose stages are queued together and
    // overlap (BackendOptions::time_stages times them one by one, more slowly).
    double whole_steps = 0.0;
    double total() const {
        return free_flight + sphere_update + contact_search + resolution + noise + whole_steps;
    }
};

// Which executor steps the state.
enum class BackendKind {
    cpu,  // the host's cores (engine/cpu/): the same bits on any number of threads
    gpu,  // a CUDA device (engine/cuda/): the data-parallel step of engine/parallel/
    // The GPU's data-parallel step run by host loops: the same algorithm as `gpu` without a
    // device, for tests and for checking a device's results. Not offered to users.
    gpu_on_host,
};
const char* to_string(BackendKind kind);

// The most threads a step may run on: every entry point (run.threads, the command lines'
// --threads, Python's threads=) takes [1, kMaxThreads] and Simulation refuses any other, before
// OpenMP is asked for a team it cannot start.
inline constexpr int kMaxThreads = 256;

// How the step is executed. On one backend the trajectory does not depend on the threads. The
// GPU backend runs the CPU's algorithm (gpu_on_host gives the CPU's bits); on a device the
// rounding may differ, so the promise is statistical equality with the CPU (architecture.md).
struct BackendOptions {
    int threads = 1;  // OpenMP threads of the CPU backend (and of gpu_on_host), >= 1
    // Simulation::step throws BlowUpError after a step that crosses a blow-up bound
    // (state_check.hpp). Off only for tests that start from deliberately impossible states.
    bool stop_on_blow_up = true;
    BackendKind backend = BackendKind::cpu;
    // The CPU backend flies only the bodies that can touch something, and the others in jumps
    // (cpu/coasting_backend.hpp): the same physics at the same dt, equal to the step that flies
    // every body to round-off, not to the bit. Ignored by the data-parallel backends.
    bool coasting = false;
    // The data-parallel backends wait for each stage to end so as to time it (StageProfile), and
    // queue no run of steps as one graph: slower, for profiles. The CPU always times its stages.
    bool time_stages = false;
};

// Every sphere of every body in body order: body b owns spheres first_of[b] .. first_of[b+1]−1,
// in the order of its shape's spheres; centres in the world, x and y not wrapped.
struct SphereView {
    std::span<const std::uint32_t> body;
    std::span<const double> radius;  // mm
    std::span<const Vec3> position;  // mm
    std::span<const std::uint32_t> first_of;

    std::size_t size() const { return body.size(); }
};

class StepBackend {
  public:
    virtual ~StepBackend() = default;
    virtual const char* name() const = 0;

    // Moves the state by one step. Overwrites `stats`, adds each stage's time to `profile`.
    virtual void step(const StepContext& context, StepStatistics& stats, StageProfile& profile) = 0;

    // One step for each context, in order, stopping after a step that crosses `bounds` (none:
    // never). The CPU steps them one by one; a device queues them together and reads its
    // statistics once at the end.
    virtual StepsDone run_steps(std::span<const StepContext> contexts, const BlowUpBounds* bounds,
                                StageProfile& profile);

    // The state on the host. A backend whose state lives elsewhere copies it here first.
    virtual const BodyState& bodies() const = 0;
    // The spheres and contacts of the last step, for tests and diagnostics.
    virtual SphereView spheres() const = 0;
    virtual const std::vector<Contact>& contacts() const = 0;
    // How often the neighbour list was built since construction.
    virtual std::uint64_t pair_list_builds() const = 0;
    // Changes the CPU threads between steps (the trajectory does not depend on them).
    virtual void set_threads(int threads) = 0;
};

}  // namespace rodsea
