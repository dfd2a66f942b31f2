#pragma once
// An observable of `rodsea analyze`: one or more compute objects of analysis/ (arrays in, arrays
// out) with what the output layer needs to present them: names, units, descriptions, the tables,
// maps and labels of the analysis files. The driver owns the frame loop, the steady window and
// the shared neighbour grids, so every observable sees the same frames through the same
// FrameContext.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rodsea/analysis/statistics.hpp"
#include "rodsea/analyze/analysis_frame.hpp"
#include "rodsea/analyze/frame_context.hpp"
#include "rodsea/io/analysis_h5.hpp"

namespace rodsea {

// The run as the analysis sees it, fixed before the first frame.
struct AnalysisSetup {
    PeriodicBox2D box;                 // mm
    std::vector<SpeciesInfo> species;  // in the run's species order
    double frame_interval = 0.0;       // s between consecutive frames
    std::size_t steady_frames = 0;     // frames inside the averaged window
    std::size_t frames = 0;            // every frame of the run analysed
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

// Maps and labels go to analysis.h5 as the io layer lays them out.
using MapResult = AnalysisMap;
using LabelResult = AnalysisLabels;
using DatasetResult = AnalysisDataset;

struct ObservableResults {
    std::string observable;
    std::vector<ParameterValue> parameters;
    std::vector<ScalarResult> scalars;
    std::vector<TableResult> tables;
    std::vector<MapResult> maps;
    std::vector<LabelResult> labels;
    std::vector<DatasetResult> datasets;
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

// A rate of independent events: `events` counted in `seconds` (per `per` of something else,
// e.g. the box area), with the Poisson error √max(events, 1); NaN without time.
Estimate rate_estimate(std::size_t events, double seconds, double per = 1.0);

// The steady window's length in seconds, from its first frame to its last: events are counted
// after the first frame, up to and including the last (0 for a window of one frame).
double steady_seconds(const AnalysisSetup& setup);

}  // namespace rodsea
