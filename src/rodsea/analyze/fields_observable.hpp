#pragma once
// Coarse-grained fields (beyond the paper, docs/analysis.md; the End Matter's continuum fields),
// every frame, on a grid of cells of side fields.cell with cloud-in-cell weights
// (analysis/coarse_grained_fields.hpp): per species its area fraction and velocity, the
// polarisation p of polar rods and the nematic tensor Q of every rod species. analysis.h5 holds
// each map as a time series (every fields.every-th frame, single precision) and its steady-window
// average. With polar rods and a medium it also measures, per frame, the interface between
// polar-rich and medium-rich regions: the level line where the polar rods' share of the local area
// fraction crosses fields.interface_level (the End Matter's mechanism: the alignment gain α grows
// with it).
#include <string>
#include <vector>

#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

// Throws InvalidParameter naming fields.every when the kept maps would not fit in memory.
void check_field_series_memory(const AnalysisSetup& setup, const AnalysisOptions& options);

class FieldsObservable final : public Observable {
  public:
    FieldsObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "fields"; }
    bool wants_transient() const override { return true; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    // One map of one species: its kept time series and the sums of its steady average.
    struct Map {
        std::uint32_t species = 0;
        std::string field, unit, description;
        std::vector<double> GroupFields::*values = nullptr;
        bool weighted = false;  // averaged with each cell's body weight (p, Q, v); else plainly
        std::vector<float> series;
        std::vector<double> sum, weight;
    };

    AnalysisSetup setup_;
    double cell_;
    int every_;
    double level_;
    FieldGrid grid_;
    std::vector<Map> maps_;
    std::size_t frames_seen_ = 0, steady_frames_ = 0;
    std::vector<double> kept_times_;
    std::vector<std::int32_t> kept_steady_;
    bool interface_ = false;
    std::vector<double> times_, length_, rich_;
    std::vector<char> steady_;
};

}  // namespace rodsea
