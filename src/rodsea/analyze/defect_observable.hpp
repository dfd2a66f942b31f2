#pragma once
// Nematic defects of the medium (beyond the paper, docs/analysis.md): every frame, the defects of
// the director field of the medium's rods on the fields.cell grid (analysis/nematic_defects.hpp),
// counted by charge, and followed in time (analysis/defect_tracks.hpp): each defect's track, ±
// pairs created and annihilated, lone births and deaths. Steady means of the counts and density,
// rates of pair creation and annihilation, lifetimes of the ±1/2 tracks; every defect of every
// frame, with its track, in analysis.h5.
#include <string>
#include <vector>

#include "rodsea/analysis/defect_tracks.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class DefectObservable final : public Observable {
  public:
    DefectObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "defects"; }
    bool wants_transient() const override { return true; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    AnalysisSetup setup_;
    double cell_, link_, pair_;
    DefectTracker tracker_;
    std::vector<double> times_, plus_half_, minus_half_, plus_one_, minus_one_, charge_;
    std::vector<char> steady_;
    double steady_from_ = -1.0;  // s, the first steady frame's time
};

}  // namespace rodsea
