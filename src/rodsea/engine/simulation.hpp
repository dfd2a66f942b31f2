#pragma once
// The programmatic entry to the engine: build from parameters and bodies, step, read the state.
//
//   Simulation sim(params, bodies);   // validates everything first, throws InvalidParameter
//   sim.run(1000);                    // 1000 steps of dt
//   sim.bodies().position[0];
//
// One step is a short script of named stages (see step()), each timed into profile().
#include <cstdint>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/contact.hpp"
#include "rodsea/engine/contact_resolution.hpp"
#include "rodsea/engine/contact_search.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/engine/plate_projection.hpp"
#include "rodsea/engine/plates.hpp"
#include "rodsea/engine/sphere_table.hpp"

namespace rodsea {

struct StepStatistics {
    size_t body_contacts = 0;
    size_t plate_contacts = 0;
    int sweeps = 0;
    size_t impulses = 0;
    size_t body_collisions = 0;   // impulses at approach speeds above kCollisionSpeed
    size_t plate_collisions = 0;  // the same with a plate
    size_t unresolved = 0;
    size_t noise_kicks = 0;
    double max_overlap_fraction = 0.0;  // largest overlap / smaller radius found this step
};

// Accumulated over every step since construction.
struct RunTotals {
    std::uint64_t impulses = 0;
    std::uint64_t unresolved = 0;
    std::uint64_t noise_kicks = 0;
    int max_sweeps = 0;
    double max_overlap_fraction = 0.0;
};

// Wall-clock seconds spent in each stage.
struct StageProfile {
    double free_flight = 0.0;
    double sphere_update = 0.0;
    double contact_search = 0.0;
    double resolution = 0.0;  // impulses and the projection out of the plates
    double noise = 0.0;
    double total() const {
        return free_flight + sphere_update + contact_search + resolution + noise;
    }
};

class Simulation {
  public:
    // Throws InvalidParameter for bad parameters, an empty body list, an unknown species index,
    // non-finite state, or a body that does not lie between the plates at t = 0.
    Simulation(EngineParameters params, BodyState bodies);

    // Continues a run from a checkpointed state after `step_count` steps. The state came from
    // the engine, so a body may touch a plate within the usual small overlap: only the species
    // indices and finiteness are checked, not the gap. Stepping on gives the same trajectory,
    // bit for bit, as the run that was never stopped (all inter-step state is in the bodies and
    // the step counter; noise signs hash the step number).
    static Simulation resume(EngineParameters params, BodyState bodies, std::uint64_t step_count);

    void step();
    void run(std::uint64_t steps);

    // OpenMP threads for the parallel stages (default 1). Every stage gives the same bits on any
    // number of threads, so this changes the speed only. Throws InvalidParameter below 1.
    void set_threads(int threads);
    int threads() const { return threads_; }

    double time() const { return static_cast<double>(step_count_) * params_.dt; }
    std::uint64_t step_count() const { return step_count_; }
    PlateState plates() const { return plate_state(params_.drive, time()); }

    const EngineParameters& parameters() const { return params_; }
    const BodyState& bodies() const { return bodies_; }
    const SphereTable& spheres() const { return spheres_; }
    const std::vector<Contact>& contacts() const { return contacts_; }  // of the last step
    const StepStatistics& last_step() const { return last_; }
    const RunTotals& totals() const { return totals_; }
    const StageProfile& profile() const { return profile_; }
    std::uint64_t pair_list_builds() const { return finder_.pair_list_builds(); }

    double kinetic_energy() const;                   // mass units · mm²/s²
    Vec3 linear_momentum() const;                    // mass units · mm/s
    Vec3 angular_momentum(const Vec3& about) const;  // about a fixed point (no unwrapping)
    std::uint64_t state_hash() const;                // FNV-1a over every bit of the state

  private:
    struct Resumed {};
    Simulation(EngineParameters params, BodyState bodies, std::uint64_t step_count, Resumed);

    EngineParameters params_;
    BodyState bodies_;
    std::uint64_t step_count_ = 0;
    int threads_ = 1;

    // Scratch reused every step: no allocation in the steady state.
    SphereTable spheres_;
    ContactFinder finder_;
    std::vector<Contact> contacts_;
    InverseInertia inverse_inertia_;
    ContactResolver resolver_;
    std::vector<PlateHit> plate_hits_;
    PlateProjection plate_projection_;

    StepStatistics last_;
    RunTotals totals_;
    StageProfile profile_;
};

}  // namespace rodsea
