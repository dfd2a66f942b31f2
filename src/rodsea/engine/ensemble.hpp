#pragma once
// Many independent systems stepped together: a phase diagram's dozens of small systems, each too
// small to fill a GPU, share one device's kernels (each kernel's elements are the bodies,
// spheres or contacts of every system). On the CPU, with T threads and M systems, they step side
// by side, min(T, M) at a time on one thread each (small systems use threads far better one per
// system than all on one), unless T >= 2M: then one after another, each on all T. Side by side,
// each worker keeps its systems from step to step, dealt by what their steps cost as measured
// (work_shares.hpp; at one area fraction, short rods cost twice what long rods do per sphere).
// Each system steps exactly as it would alone on the same backend: the same bits, on any number
// of threads and whichever worker steps it.
//
//   std::vector<Simulation> systems;
//   for (double phi : {0.2, 0.5, 0.8}) systems.emplace_back(params(phi), bodies(phi));
//   Ensemble ensemble(std::move(systems), {.backend = BackendKind::gpu});
//   ensemble.run(100000);
//   ensemble.bodies(1);  ensemble.time(1);
//
// The systems come as Simulations, new or resumed: they are validated as Simulations are, and
// each keeps its own parameters (box, drive, species, noise, seed, solver) and step count; they
// must share dt only in the sense that each step advances every system by its own dt.
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <vector>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/engine/work_shares.hpp"

namespace rodsea {

namespace parallel {
class EnsembleStepper;
}

class Ensemble {
  public:
    // Throws InvalidParameter for no systems, or for a backend this build or machine cannot
    // run (naming "backend"). options.threads: the CPU backend's, shared among the systems.
    Ensemble(std::vector<Simulation> systems, BackendOptions options);
    Ensemble(Ensemble&&) noexcept;
    Ensemble& operator=(Ensemble&&) noexcept;
    ~Ensemble();

    std::size_t size() const { return params_.size(); }
    const char* backend_name() const;

    // Every system by one step. Throws BlowUpError (its message naming the system) after a step
    // in which one crossed a blow-up bound, as Simulation::step does; every system has stepped,
    // and blow_up(m) says which ones crossed (the others go on as if nothing had happened).
    void step();
    // Every system by `steps` steps, the same bits as as many calls of step(). On the CPU a
    // blow-up stops every system after that step; a device takes the steps in runs of up to
    // Simulation::kStepsPerRun and stops a system that blows up after that step while the
    // others finish the run (each one's step_count() says where it is), then throws.
    void run(std::uint64_t steps);
    // Why system m blew up in the last step, if it did; its state is then meaningless.
    const std::optional<BlowUp>& blow_up(std::size_t m) const { return blown_[m]; }

    // Drops these systems (indices into the current ensemble, any order); the others keep their
    // state and step on bit for bit, renumbered in their order. A run whose system is done
    // frees its share of the kernels.
    void retire(const std::vector<std::size_t>& systems);
    // Between steps, as Simulation::set_threads: the trajectory does not depend on it.
    void set_threads(int threads);

    const EngineParameters& parameters(std::size_t m) const { return params_[m]; }
    std::uint64_t step_count(std::size_t m) const { return step_count_[m]; }
    double time(std::size_t m) const { return static_cast<double>(step_count_[m]) * params_[m].dt; }
    const BodyState& bodies(std::size_t m) const;
    const StepStatistics& last_step(std::size_t m) const { return last_[m]; }
    const RunTotals& totals(std::size_t m) const { return totals_[m]; }
    // The steps of system m in the last call of step() or run(), together.
    const StepTally& last_run(std::size_t m) const { return last_run_[m]; }
    std::uint64_t state_hash(std::size_t m) const;
    // The time of each stage over every system together.
    const StageProfile& profile() const { return profile_; }

  private:
    void step_cpu_systems();
    void run_on_stepper(std::uint64_t steps);
    int systems_side_by_side() const;
    int threads_per_system() const;
    void share_threads();
    void reshare_by_measured_cost();
    void make_stepper(const std::vector<const BodyState*>& states);

    BackendOptions options_;
    std::vector<EngineParameters> params_;
    std::vector<std::uint64_t> step_count_;
    std::vector<BlowUpBounds> bounds_;
    std::vector<StepStatistics> last_;
    std::vector<RunTotals> totals_;
    std::vector<StepTally> last_run_;
    std::vector<std::optional<BlowUp>> blown_;
    StageProfile profile_;
    // The CPU steps each Simulation; the data-parallel backends one stepper for all.
    std::vector<Simulation> cpu_systems_;
    WorkShares shares_;  // the CPU systems each worker steps
    // What each CPU system's steps cost: its stage time (StageProfile::total) at the last look,
    // and the stage time per step over the window before it (empty until the first look). The
    // shares follow the costs as a campaign's systems settle, jam or leave.
    std::vector<double> stage_time_at_look_;
    std::vector<double> step_cost_;
    std::uint64_t steps_since_look_ = 0;
    std::vector<std::exception_ptr> failed_;  // per CPU system, in the last step
    std::vector<std::unique_ptr<SpeciesTable>> species_;
    std::unique_ptr<parallel::EnsembleStepper> stepper_;
};

}  // namespace rodsea
