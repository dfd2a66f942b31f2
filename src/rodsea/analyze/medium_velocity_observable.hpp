#pragma once
// The medium's flow around polar rods (analysis/medium_velocity.hpp; paper Fig. 5b) over the
// steady frames: the profile against distance, and the value at the paper's d as a per-frame
// series, which gives its error bar. The velocities are the instantaneous ones stored in the
// trajectory, or (medium_velocity.lag = k) each body's displacement over k frames: the plates
// agitate every body in the plane at tens of mm/s, far above the flow of a few mm/s that the
// paper's "medium speed" is about.
#include <deque>
#include <span>
#include <vector>

#include "rodsea/analysis/medium_velocity.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class MediumVelocityObservable final : public Observable {
  public:
    MediumVelocityObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "medium_velocity"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    // Where the bodies were, for velocities from displacements (medium_velocity.lag).
    struct Past {
        double time = 0.0;
        std::vector<Vec3> polar, medium;
    };
    // Each body's displacement since `then`, over the time between, mm/s.
    static std::vector<Vec3> velocities(const PeriodicBox2D& box, std::span<const Vec3> now,
                                        const std::vector<Vec3>& then, double seconds);

    MediumVelocityParameters parameters_;
    MediumVelocity profile_;
    int lag_;
    double frame_interval_;
    std::deque<Past> past_;
    std::size_t measured_frames_ = 0;
    std::vector<double> along_at_d_, speed_at_d_, relative_speed_at_d_;
};

}  // namespace rodsea
