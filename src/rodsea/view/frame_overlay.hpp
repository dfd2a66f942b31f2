#pragma once
// What `rodsea render/movie --overlay` draws over the bodies (docs/visualisation.md): the medium's
// director field (a stick per cell, along the director, as long as the cell times the order S), its
// nematic defects (+1/2 a comet: a dot at the core with its tail along the defect's
// orientation; −1/2 a trefoil; ±1 a ring), and flocks followed in time (each flock's centre
// over the last seconds, an arrow along its heading and a ring on its leading rod). The fields,
// defects and flock links are those of `rodsea analyze` (analysis/), with the same defaults:
// cells of ℓ_p, DBSCAN ε = ℓ_p / 2, min_samples 3.
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/analysis/coarse_grained_fields.hpp"
#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analysis/flock_tracks.hpp"
#include "rodsea/analysis/nematic_defects.hpp"
#include "rodsea/config/run_plan.hpp"
#include "rodsea/engine/body_state.hpp"

namespace rodsea {

struct OverlayOptions {
    bool defects = false, director = false, flock_tracks = false;
    std::optional<double> cell;  // mm, of the director grid; none: ℓ_p (or 4.5 mm)
    double trail = 2.0;          // s of each flock's past drawn
    bool any() const { return defects || director || flock_tracks; }
};

// The shapes to draw on one frame, in mm.
struct OverlayShapes {
    struct Stick {
        double x, y, angle, length;
    };
    struct Trail {
        int track = 0;
        std::vector<Vec3> centres;  // oldest first, in the box
        double heading = 0.0;       // rad
        Vec3 leader;                // the leading rod's centre
    };
    double cell = 0.0;   // mm, sets the glyphs' size
    double arrow = 0.0;  // mm, a flock's heading arrow
    std::vector<Stick> director;
    std::vector<NematicDefect> defects;
    std::vector<Trail> trails;
};

class OverlayBuilder {
  public:
    // Throws InvalidParameter naming --overlay or --overlay-cell when the run cannot show the
    // overlay (no apolar rods for defects or the director, no polar rods for flock tracks) or
    // the cell does not fit the box.
    OverlayBuilder(const RunPlan& plan, const OverlayOptions& options);

    // Frames in time order: flock tracks need the past (a movie feeds every frame it draws,
    // a single picture the frames of the trail before it).
    OverlayShapes update(const BodyState& bodies, double time);

    double cell() const { return cell_; }
    // The annotation lines that explain the glyphs: one for the medium's, one for the flocks'.
    std::vector<std::string> caption() const;

  private:
    const RunPlan& plan_;
    OverlayOptions options_;
    PeriodicBox2D box_;
    double cell_ = 0.0, polar_length_ = 0.0;
    FieldGrid grid_;
    DbscanParameters flocks_;
    FlockTracker tracker_;
    std::vector<std::size_t> polar_;  // body indices of the polar rods
};

}  // namespace rodsea
