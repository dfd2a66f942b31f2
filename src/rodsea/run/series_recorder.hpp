#pragma once
// The scalar time series written every output interval: order parameters and kinetic energies
// per species from the current state, the segregation Σ and largest flock N_m as `rodsea analyze`
// measures them (structure_series.hpp), and the engine's health (largest overlap, unresolved
// contacts, sweeps, impulses) and collision rates accumulated over the interval, so that a bad
// step between two rows is not missed.
#include <string>
#include <vector>

#include "rodsea/analyze/structure_series.hpp"
#include "rodsea/config/run_plan.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/io/trajectory_file.hpp"

namespace rodsea {

class SeriesRecorder {
  public:
    explicit SeriesRecorder(const RunPlan& plan);

    const std::vector<SeriesColumn>& columns() const { return columns_; }
    // The steps since the last call join the interval.
    void accumulate(const StepTally& steps);
    // The row for the state `bodies` of a system of `params` and the interval so far.
    std::vector<double> row(const EngineParameters& params, const BodyState& bodies,
                            double steps_per_second) const;
    // Called once the row is safely written: the next row covers the steps from here.
    void start_interval() { restore_interval({0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}); }

    // The partly filled interval, for checkpoints: a resumed run then writes the same rows.
    std::vector<double> interval_state() const;
    void restore_interval(const std::vector<double>& state);
    // What is impossible in a stored interval state (a checkpoint's), or "" when nothing:
    // counts that are not whole and non-negative, more steps than an output interval has, a
    // largest overlap beyond kGrossOverlapFraction, sweeps beyond engine.max_sweeps.
    std::string interval_problem(const std::vector<double>& state) const;

  private:
    std::vector<SeriesColumn> columns_;
    size_t species_count_ = 0;
    double steps_per_output_ = 0.0, sweep_cap_ = 0.0;  // for interval_problem
    StructureSeries structure_;
    double max_overlap_ = 0.0;
    double unresolved_ = 0.0;
    double max_sweeps_ = 0.0;
    double impulses_ = 0.0;
    double body_collisions_ = 0.0;
    double plate_collisions_ = 0.0;
    double steps_ = 0.0;
};

}  // namespace rodsea
