#pragma once
// Flocks and the medium's +1/2 defects (beyond the paper, docs/analysis.md; the paper's SM4: +1/2
// defects steer and merge flocks). Every steady frame with flocks and +1/2 defects: the distance
// from each flock's centre to the nearest +1/2 defect (minimum image), beside the same distance
// from a point placed at random (averaged exactly over the grid's cell centres), so that a ratio
// below 1 says flocks sit near +1/2 defects more than chance; and the alignment cos(ψ − φ) of the
// flock's direction of motion ψ (the mean heading of its rods, which self-propel along their axes)
// with that defect's orientation φ: 0 when unrelated, ±1 when along or against it.
#include <string>
#include <vector>

#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class FlockDefectObservable final : public Observable {
  public:
    FlockDefectObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "flock_defects"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    AnalysisSetup setup_;
    DbscanParameters flocks_;
    double cell_;
    double bin_;  // mm, of the distance histograms
    std::vector<double> flock_distance_, random_distance_, alignment_;  // per frame
    std::vector<double> flock_histogram_, random_histogram_;
    std::vector<std::vector<double>> rows_;  // per flock and frame
    std::size_t frames_without_ = 0;
};

}  // namespace rodsea
