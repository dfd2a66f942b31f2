#pragma once
// The programmatic entry to the engine: build from parameters and bodies, step, read the state.
//
//   Simulation sim(params, bodies, {.threads = 2});  // checks everything: InvalidParameter
//   sim.run(1000);                                   // 1000 steps of dt
//   sim.bodies().position[0];                        // mm
//
// Each step builds a StepContext (dt, gravity, box, the plates at the end of the step, the solver
// settings, ε, seed and step number) and hands it to the backend, which owns the state and runs
// the stages (step_backend.hpp), each timed into profile().
#include <cstdint>
#include <memory>
#include <vector>

#include "rodsea/engine/body_state.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea {

// The context of step number `step` (counted from 1): the plates where that step ends.
StepContext step_context(const EngineParameters& params, std::uint64_t step);

// Every step since construction.
using RunTotals = StepTally;

// FNV-1a over the step count and every bit of the state: equal hashes, equal trajectories.
std::uint64_t state_hash(const BodyState& state, std::uint64_t step_count);

class Simulation {
  public:
    // Throws InvalidParameter for bad parameters or options, an empty body list, an unknown
    // species index, non-finite state, or a body that does not lie between the plates at t = 0.
    Simulation(EngineParameters params, BodyState bodies, BackendOptions options = {});

    // Continues a run from a checkpointed state after `step_count` steps. The state came from
    // the engine, so a body may touch a plate within the usual small overlap: it is checked as
    // find_state_problem(resumed) checks it (not for overlaps between bodies: the caller does
    // that where it costs nothing to wait for, find_gross_overlap). Stepping on gives the same
    // trajectory, bit for bit, as the run that was never stopped (all inter-step state is in the
    // bodies and the step counter; noise signs hash the step number).
    static Simulation resume(EngineParameters params, BodyState bodies, std::uint64_t step_count,
                             BackendOptions options = {});

    Simulation(Simulation&&) noexcept;
    Simulation& operator=(Simulation&&) noexcept;
    ~Simulation();

    // Throws BlowUpError (state_check.hpp) after a step that crossed a blow-up bound: a speed
    // the time step cannot resolve, a gross overlap, or too many unresolved contacts. The state
    // is then meaningless; keep a copy of the last one you trust.
    void step();
    // `steps` steps; a device takes them in runs of up to kStepsPerRun, reading its statistics
    // once per run. The same bits as as many calls of step().
    void run(std::uint64_t steps);
    static constexpr std::uint64_t kStepsPerRun = 1024;

    const BackendOptions& options() const { return options_; }
    // Between steps: the trajectory is the same bit for bit on any number of threads, so a run
    // may use fewer when other processes take its cores. Throws InvalidParameter below 1.
    void set_threads(int threads);
    const char* backend_name() const { return backend_->name(); }

    double time() const { return static_cast<double>(step_count_) * params_.dt; }
    std::uint64_t step_count() const { return step_count_; }
    physics::PlateState plates() const {
        return physics::plate_state(params_.drive.motion(), time());
    }

    const EngineParameters& parameters() const { return params_; }
    const BodyState& bodies() const { return backend_->bodies(); }
    SphereView spheres() const { return backend_->spheres(); }
    const std::vector<Contact>& contacts() const { return backend_->contacts(); }  // last step
    const StepStatistics& last_step() const { return last_; }
    const RunTotals& totals() const { return totals_; }
    const StageProfile& profile() const { return profile_; }
    std::uint64_t pair_list_builds() const { return backend_->pair_list_builds(); }

    double kinetic_energy() const;                   // mass units · mm²/s²
    Vec3 linear_momentum() const;                    // mass units · mm/s
    Vec3 angular_momentum(const Vec3& about) const;  // about a fixed point (no unwrapping)
    std::uint64_t state_hash() const;                // FNV-1a over every bit of the state

  private:
    Simulation(EngineParameters params, BodyState bodies, std::uint64_t step_count,
               BackendOptions options, bool fresh_start);

    EngineParameters params_;
    BackendOptions options_;
    // On the heap: the backend keeps a reference to it, which must survive a move.
    std::unique_ptr<SpeciesTable> species_;
    std::unique_ptr<StepBackend> backend_;
    std::uint64_t step_count_ = 0;
    BlowUpBounds bounds_;

    StepStatistics last_;
    RunTotals totals_;
    StageProfile profile_;
};

}  // namespace rodsea
