#pragma once
// A top view of one frame, drawn with Cairo: every body as its true projected outline (the
// union of its spheres' discs, tilted bodies included), polar rods coloured by the direction of
// their axis on a cyclic wheel (or by flock), the medium in a neutral tone (or by its nematic
// axis), periodic images where a body crosses the box edge, and, unless switched off, the time,
// area fractions and order parameters in a strip above the view, a scale bar in mm and the
// colour legend in a strip below it, so that no annotation hides a body.
//
// Image coordinates: column = (x − x0)·s, row = top + (y1 − y)·s with s = width / (x1 − x0)
// pixels per mm and `top` the height of the strip above (0 without annotations), so +y points
// up as in the paper's figures; the view's height is its aspect rounded to an even number of
// pixels, and so is the strips' (H.264 needs even sizes).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/config/run_plan.hpp"
#include "rodsea/engine/body_state.hpp"
#include "rodsea/view/frame_overlay.hpp"

// Cairo stays out of this header.
typedef struct _cairo cairo_t;

namespace rodsea {

enum class PolarColouring { direction, flock, uniform };
enum class MediumColouring { neutral, nematic };

// The part of the box shown, mm; 0 ≤ x0 < x1 ≤ L_x and 0 ≤ y0 < y1 ≤ L_y.
struct ViewRegion {
    double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
};

struct RenderOptions {
    int width = 1200;                  // pixels, [64, 16384]
    std::optional<ViewRegion> region;  // none: the whole box
    PolarColouring polar = PolarColouring::direction;
    MediumColouring medium = MediumColouring::neutral;
    bool annotate = true;             // text, scale bar and legend
    std::optional<double> flock_eps;  // mm, DBSCAN ε for flock colours; none: ℓ_p / 2
    int flock_min_samples = 3;        // as `rodsea analyze` (docs/model.md CHOICE)
    OverlayOptions overlay;           // drawn over the bodies
};

// Premultiplied ARGB32 pixels (Cairo's layout), row-major from the top row. Opaque here.
struct Image {
    int width = 0, height = 0;
    std::vector<std::uint32_t> pixels;

    std::uint32_t at(int column, int row) const {
        return pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(column)];
    }
};

// What the text in the corner says about the frame besides what the bodies show.
struct FrameLabel {
    double time = 0.0;  // s
    std::int64_t step = 0;
    std::size_t frame = 0;
};

class FrameRenderer {
  public:
    // Checks the options against the run (region inside the box, size, ε) and throws
    // InvalidParameter naming the flag (--region, --size, --flock-eps) otherwise.
    FrameRenderer(const RunPlan& plan, const RenderOptions& options);

    int width() const { return width_; }
    int height() const { return height_; }
    const ViewRegion& region() const { return region_; }

    // With flock tracks overlaid the renderer remembers the frames it drew (their tracks), so
    // frames must come in time order; `remember` feeds it a frame without drawing it (the
    // frames before a single picture's).
    Image render(const BodyState& bodies, const FrameLabel& label) const;
    // The same into an existing image of the right size (a movie reuses one buffer).
    void render_into(const BodyState& bodies, const FrameLabel& label, Image& image) const;
    void remember(const BodyState& bodies, double time) const;

  private:
    // What the corner text and the legend say beyond the run: the number of flocks coloured,
    // and which colour wheels to explain.
    struct Legend {
        int flocks = 0;
        bool polar_wheel = false;
        bool medium_wheel = false;
    };
    void annotate(cairo_t* cr, const BodyState& bodies, const FrameLabel& label,
                  const Legend& legend) const;
    // The corner text's lines with what does not change between frames (the first, the time,
    // is filled per frame), and whether colour wheels are drawn: they set the strips' height.
    std::vector<std::string> annotation_lines() const;
    bool legend_wheels() const;

    const RunPlan& plan_;
    RenderOptions options_;
    ViewRegion region_;
    int width_ = 0, height_ = 0;
    int top_ = 0, bottom_ = 0;  // pixels of the annotation strips above and below the view
    double scale_ = 1.0;        // pixels per mm
    DbscanParameters flocks_;
    mutable std::unique_ptr<OverlayBuilder> overlay_;  // none without --overlay
};

}  // namespace rodsea
