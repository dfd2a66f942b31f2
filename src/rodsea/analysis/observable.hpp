#pragma once
// An observable is a compute object: parameters in (constructor), compute(frame) once per frame,
// results out (finish). The driver owns the frame loop and the shared neighbour layer, so every
// observable sees the same frames through the same FrameContext.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rodsea/analysis/analysis_frame.hpp"
#include "rodsea/analysis/frame_context.hpp"
#include "rodsea/analysis/statistics.hpp"

namespace rodsea {

// The run as the analysis sees it, fixed before the first frame.
struct AnalysisSetup {
    PeriodicBox2D box;                 // mm
    std::vector<SpeciesInfo> species;  // in the run's species order
    double frame_interval = 0.0;       // s between consecutive frames
    std::size_t steady_frames = 0;     // frames inside the averaged window
    int blocks = 4;                    // time blocks for the error bars of window averages

    bool has_kind(BodyKind kind) const;
    double polar_length() const;  // mm, ℓ_p of the first polar species (0 without one)
    long long count_of(BodyKind kind) const;
    long long polar_count() const { return count_of(BodyKind::polar_rod); }
    long long total_count() const;
    // The block (0 .. blocks−1) of the `steady_index`-th steady frame.
    int block_of(std::size_t steady_index) const;
};

struct ParameterValue {
    std::string name;
    double value = 0.0;
    std::string unit;
};

struct ScalarResult {
    std::string name;
    std::string unit;
    std::string description;
    Estimate estimate;
};

// A curve or a time series: one CSV file.
struct TableResult {
    std::string name;
    std::string description;
    std::vector<std::string> columns;  // each "name [unit]" is written as the CSV header
    std::vector<std::string> units;
    std::vector<std::vector<double>> rows;
};

// A polar map, values[r_bin * theta_bins + theta_bin]: one HDF5 dataset with its bin edges.
struct MapResult {
    std::string name;
    std::string description;
    std::string unit;
    std::vector<double> r_edges;      // mm
    std::vector<double> theta_edges;  // rad
    std::vector<double> values;
};

// Per-frame integer labels of a fixed set of bodies (flock labels), [frames][bodies].
struct LabelResult {
    std::string name;
    std::string description;
    std::vector<std::uint32_t> bodies;  // body indices in the trajectory
    std::vector<double> times;          // s
    std::vector<std::int32_t> labels;
};

struct ObservableResults {
    std::string observable;
    std::vector<ParameterValue> parameters;
    std::vector<ScalarResult> scalars;
    std::vector<TableResult> tables;
    std::vector<MapResult> maps;
    std::vector<LabelResult> labels;
    std::vector<std::string> notes;
    std::size_t frames = 0;  // frames this observable computed
    double seconds = 0.0;    // wall time in compute()
};

class Observable {
  public:
    virtual ~Observable() = default;
    virtual std::string name() const = 0;
    // Observables that record a time series over the whole run also see the frames before the
    // steady window (frame.steady() is false there); all others see steady frames only.
    virtual bool wants_transient() const { return false; }
    virtual void compute(const FrameContext& frame) = 0;
    virtual ObservableResults finish() = 0;
};

// Steady-state mean of a per-frame series, with the window's frames selected by `steady`.
Estimate steady_estimate(std::span<const double> series, std::span<const char> steady);

}  // namespace rodsea
