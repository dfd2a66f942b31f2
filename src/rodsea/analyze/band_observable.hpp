#pragma once
// Bands of polar rods every frame (analysis/density_modes.hpp): the longest-wavelength density
// modes of the polar rods, split into the transverse and the longitudinal band relative to
// their axis of motion, the director of their headings (either heading: lanes of rods moving
// both ways along one axis are one longitudinal band).
#include <string>
#include <vector>

#include "rodsea/analysis/density_modes.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class BandObservable final : public Observable {
  public:
    BandObservable(const AnalysisSetup& setup, const AnalysisOptions& options)
        : setup_(setup), floors_(options.band_threshold) {}
    std::string name() const override { return "bands"; }
    bool wants_transient() const override { return true; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    // band_<kind>_present and band_<kind>_drift from one kind of band's amplitude, position and
    // mode in every frame.
    template <class Amplitude, class At, class Mode>
    void add_band_motion(ObservableResults& r, const std::string& kind, const std::string& what,
                         double least, Amplitude amplitude, At at, Mode mode) const;

    AnalysisSetup setup_;
    double floors_;  // bands.threshold: a band stands this many random means
    std::vector<double> times_, axis_;
    std::vector<BandAmplitudes> amplitudes_;
    std::vector<char> steady_;
};

}  // namespace rodsea
