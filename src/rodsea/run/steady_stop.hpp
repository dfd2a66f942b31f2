#pragma once
// Stop when steady (time.steady_samples): the run keeps the order series the steady window is
// chosen from (structure_series.hpp) and, at every frame, asks whether the window
// (steady_state.hpp) already holds the samples asked for. Campaigns then spend their compute only
// where it is needed: a point that settles fast stops early, a slow one runs to its duration.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/analysis/steady_state.hpp"
#include "rodsea/config/run_plan.hpp"
#include "rodsea/io/trajectory_file.hpp"

namespace rodsea {

class TrajectoryReader;

// Throws InvalidParameter naming time.steady_series when it is neither "all" nor one of the
// run's order series; called before any work (run and info).
void check_steady_series(const RunPlan& plan);

// Fewer frames than this are not judged: Sokal's τ_int and Chodera's start need a series many
// correlation times long, and a window of a dozen frames is not a steady state.
inline constexpr std::size_t kSteadyMinimumFrames = 50;

struct SteadyVerdict {
    std::size_t first_frame = 0;  // of the window
    std::string decided_by;       // the series whose start set it
    std::string counted;          // the series whose samples were counted (the fewest, for all)
    double n_eff = 0.0;           // its independent samples in the window
};

class SteadyStop {
  public:
    // `columns`: the time-series columns in row order, as SeriesRecorder writes them.
    SteadyStop(const RunPlan& plan, const std::vector<SeriesColumn>& columns);

    bool active() const { return samples_ > 0; }
    // The series so far, for a resumed run: its first `frames` rows as stored.
    void restore(const TrajectoryReader& reader, std::size_t frames);
    void add_row(const std::vector<double>& row);
    // Set once the window holds the samples of the counted series (every order series, or the
    // one named), none of them drifting.
    std::optional<SteadyVerdict> verdict() const;

  private:
    long long samples_ = 0;
    std::string counted_;             // "all" or one column
    std::vector<std::size_t> index_;  // of each series in a row
    std::vector<NamedSeries> series_;
};

}  // namespace rodsea
