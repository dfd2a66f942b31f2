#include "rodsea/view/frame_renderer.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/error.hpp"
#include "rodsea/view/colour_wheel.hpp"

namespace rodsea {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr Rgb kBackground{1.0, 1.0, 1.0};
constexpr Rgb kOutline{0.22, 0.22, 0.22};
constexpr Rgb kMediumFill{0.78, 0.78, 0.76};
constexpr Rgb kPolarUniform{0.85, 0.25, 0.10};
// Nematic colours are drawn in this many bins of the π period: one fill per bin instead of one
// per body (10⁵ fills dominate the render time); 2° bins are finer than the eye separates.
constexpr int kNematicBins = 90;

bool is_polar(const Species& s) {
    return s.kind == BodyKind::polar_rod;
}

void set_colour(cairo_t* cr, const Rgb& c) {
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

// Per species: the spheres, and how far the body reaches from its centre in the plane, so that
// bodies far from the view (and their periodic images) cost one test.
struct SpeciesGeometry {
    const Shape* shape = nullptr;
    double reach = 0.0;  // mm
};

std::vector<SpeciesGeometry> geometry_of(const RunPlan& plan) {
    std::vector<SpeciesGeometry> g;
    for (const Species& s : plan.engine.species) {
        SpeciesGeometry sg{&s.shape, 0.0};
        for (std::size_t k = 0; k < s.shape.sphere_count(); ++k)
            sg.reach = std::max(sg.reach, norm(s.shape.offsets[k]) + s.shape.radii[k]);
        g.push_back(sg);
    }
    return g;
}

// Appends the body's discs, shrunk by `inset` mm, to the current path for every periodic image
// that reaches into the view. Nonzero winding makes their union one filled outline.
//
// A disc is drawn as a regular polygon whose edges stray at most a quarter pixel from the circle:
// as exact as the pixels can show, and about half the cost of Cairo's arcs, which it flattens
// from Bézier curves each time.
class DiscPainter {
  public:
    DiscPainter(cairo_t* cr, const RunPlan& plan, const ViewRegion& view, double pixels_per_mm)
        : cr_(cr),
          geometry_(geometry_of(plan)),
          view_(view),
          margin_(1.0 / pixels_per_mm),
          pixels_per_mm_(pixels_per_mm),
          lx_(plan.engine.box.lx),
          ly_(plan.engine.box.ly) {}

    void add(const BodyState& bodies, std::size_t b, double inset) const {
        const SpeciesGeometry& g = geometry_[bodies.species[b]];
        const Vec3& c = bodies.position[b];
        const double reach = g.reach + margin_;
        for (int i = -1; i <= 1; ++i) {
            const double cx = c.x + i * lx_;
            if (cx + reach < view_.x0 || cx - reach > view_.x1) continue;
            for (int j = -1; j <= 1; ++j) {
                const double cy = c.y + j * ly_;
                if (cy + reach < view_.y0 || cy - reach > view_.y1) continue;
                add_image(g, {cx, cy, c.z}, bodies.orientation[b], inset);
            }
        }
    }

  private:
    void add_image(const SpeciesGeometry& g, const Vec3& centre, const Quat& q,
                   double inset) const {
        for (std::size_t k = 0; k < g.shape->sphere_count(); ++k) {
            const double r = g.shape->radii[k] - inset;
            if (r <= 0.0) continue;
            const Vec3 p = centre + rotate(q, g.shape->offsets[k]);
            const std::vector<std::array<double, 2>>& corners = polygon(r * pixels_per_mm_);
            cairo_move_to(cr_, p.x + r * corners[0][0], p.y + r * corners[0][1]);
            for (std::size_t i = 1; i < corners.size(); ++i)
                cairo_line_to(cr_, p.x + r * corners[i][0], p.y + r * corners[i][1]);
            cairo_close_path(cr_);
        }
    }

    // Unit-circle corners for a disc `radius_px` pixels across: n sides with the sagitta
    // r (1 − cos(π/n)) at most 0.25 px. Corners run anticlockwise for every disc, so that the
    // nonzero rule fills their union.
    const std::vector<std::array<double, 2>>& polygon(double radius_px) const {
        const double half_angle = std::acos(std::max(-1.0, 1.0 - 0.25 / radius_px));
        const int sides =
            std::clamp(static_cast<int>(std::ceil(std::numbers::pi / half_angle)), 6, 256);
        std::vector<std::array<double, 2>>& corners = polygons_[sides];
        if (corners.empty())
            for (int i = 0; i < sides; ++i)
                corners.push_back({std::cos(kTwoPi * i / sides), std::sin(kTwoPi * i / sides)});
        return corners;
    }

    cairo_t* cr_;
    std::vector<SpeciesGeometry> geometry_;
    ViewRegion view_;
    double margin_, pixels_per_mm_, lx_, ly_;
    mutable std::map<int, std::vector<std::array<double, 2>>> polygons_;
};

// 1, 2 or 5 × 10^k mm, the largest not above a fifth of the view's width.
double scale_bar_length(double view_width) {
    const double target = view_width / 5.0;
    const double decade = std::pow(10.0, std::floor(std::log10(target)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * decade <= target) return m * decade;
    return decade;
}

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

const char* plural_kind(BodyKind kind) {
    switch (kind) {
        case BodyKind::polar_rod:
            return "polar rods";
        case BodyKind::apolar_rod:
            return "apolar rods";
        case BodyKind::bead:
            return "beads";
    }
    return "bodies";
}

// The annotations' font size in pixels for an image `width` pixels wide.
double annotation_font(int width) {
    return std::clamp(static_cast<double>(width) / 75.0, 10.0, 28.0);
}

// A colour wheel's radius in pixels.
double wheel_radius(int width) {
    return std::max(2.2 * annotation_font(width), static_cast<double>(width) / 28.0);
}

// The strips above and below the box that hold the annotations, so that none covers a body:
// the text block above (`lines` lines), the scale bar and the colour wheels below.
int header_height(int width, int lines) {
    const double font = annotation_font(width);
    return static_cast<int>(std::ceil(font + 1.35 * font * static_cast<double>(lines)));
}
int footer_height(int width, bool wheels) {
    const double font = annotation_font(width);
    return static_cast<int>(
        std::ceil(wheels ? 4.5 * font + 2.0 * wheel_radius(width) : 3.5 * font));
}

// Annotations are drawn in pixels, after the bodies, on the identity transform, in the strips
// above and below the box.
class Annotator {
  public:
    Annotator(cairo_t* cr, int width, int height)
        : cr_(cr), width_(width), height_(height), font_(annotation_font(width)) {
        cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                               CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr, font_);
    }

    double font() const { return font_; }

    // Lines of text in the strip above the box.
    void text_block(const std::vector<std::string>& lines) const {
        const double pad = 0.5 * font_, step = 1.35 * font_;
        set_colour(cr_, {0.0, 0.0, 0.0});
        for (std::size_t i = 0; i < lines.size(); ++i) {
            cairo_move_to(cr_, 2 * pad, pad + step * static_cast<double>(i + 1) - 0.1 * font_);
            cairo_show_text(cr_, lines[i].c_str());
        }
    }

    // In the strip below the box, on the left.
    void scale_bar(double length_mm, double pixels_per_mm) const {
        const double bar = length_mm * pixels_per_mm, pad = font_;
        const double y = height_ - pad;
        set_colour(cr_, {0.0, 0.0, 0.0});
        cairo_rectangle(cr_, pad, y - 0.35 * font_, bar, 0.35 * font_);
        cairo_fill(cr_);
        const std::string label = format_number(length_mm) + " mm";
        cairo_text_extents_t e;
        cairo_text_extents(cr_, label.c_str(), &e);
        cairo_move_to(cr_, pad + 0.5 * (bar - e.x_advance), y - 0.7 * font_);
        cairo_show_text(cr_, label.c_str());
    }

    // A colour ring in the strip below the box, on the right (`slot` 0 is rightmost): the
    // colour of an axis at angle θ sits at θ on the ring, measured anticlockwise from +x as in
    // the picture.
    void wheel(int slot, const std::string& caption, Rgb (*colour)(double)) const {
        const double radius = wheel_radius(width_);
        const double box = 2.0 * radius + 3.2 * font_;
        const double cx = width_ - font_ - 0.5 * box - static_cast<double>(slot) * (box + font_);
        const double cy = height_ - font_ - radius - 0.6 * font_;
        constexpr int kSegments = 180;
        for (int k = 0; k < kSegments; ++k) {
            const double a0 = kTwoPi * k / kSegments, a1 = kTwoPi * (k + 1) / kSegments;
            set_colour(cr_, colour(0.5 * (a0 + a1)));
            // Pixel rows grow downwards, so the world angle θ is drawn at −θ.
            cairo_new_path(cr_);
            cairo_arc_negative(cr_, cx, cy, radius, -a0, -a1 - 0.002);
            cairo_arc(cr_, cx, cy, 0.55 * radius, -a1 - 0.002, -a0);
            cairo_close_path(cr_);
            cairo_fill(cr_);
        }
        // The reference direction θ = 0 and the caption.
        set_colour(cr_, {0.0, 0.0, 0.0});
        cairo_set_line_width(cr_, std::max(1.0, 0.12 * font_));
        cairo_move_to(cr_, cx, cy);
        cairo_line_to(cr_, cx + 0.5 * radius, cy);
        cairo_stroke(cr_);
        cairo_set_font_size(cr_, 0.8 * font_);
        cairo_move_to(cr_, cx + 0.1 * radius, cy - 0.12 * font_);
        cairo_show_text(cr_, "0");
        cairo_text_extents_t e;
        cairo_text_extents(cr_, caption.c_str(), &e);
        cairo_move_to(cr_, cx - 0.5 * e.x_advance, cy - radius - 0.9 * font_);
        cairo_show_text(cr_, caption.c_str());
        cairo_set_font_size(cr_, font_);
    }

  private:
    cairo_t* cr_;
    int width_, height_;
    double font_;
};

// The medium first, by colour, bodies of one colour sharing a path, but 64 at most: Cairo's
// rasteriser slows down on long paths (a 10⁵-bead medium: 256 ms at 2000 px in paths of 64
// bodies, 300 ms in paths of 256).
void fill_batches(cairo_t* cr, const DiscPainter& painter, const BodyState& bodies,
                  const std::vector<std::size_t>& list, double inset, const Rgb& colour) {
    constexpr std::size_t kBatch = 64;
    set_colour(cr, colour);
    for (std::size_t first = 0; first < list.size(); first += kBatch) {
        cairo_new_path(cr);
        for (std::size_t i = first; i < std::min(list.size(), first + kBatch); ++i)
            painter.add(bodies, list[i], inset);
        cairo_fill(cr);
    }
}

// Draws the medium, grey or by its nematic axis; returns whether any rod got an axis colour.
bool draw_medium(cairo_t* cr, const DiscPainter& painter, const RunPlan& plan,
                 const BodyState& bodies, const std::vector<std::size_t>& medium, double outline,
                 bool nematic) {
    if (outline > 0.0) fill_batches(cr, painter, bodies, medium, 0.0, kOutline);
    std::vector<std::vector<std::size_t>> bins(nematic ? kNematicBins + 1 : 1);
    for (std::size_t b : medium) {
        const bool has_axis = plan.engine.species[bodies.species[b]].kind == BodyKind::apolar_rod;
        if (!nematic || !has_axis) {
            bins.back().push_back(b);
            continue;
        }
        const double theta = in_plane_angle(bodies.orientation[b]);
        const double turns = theta / std::numbers::pi - std::floor(theta / std::numbers::pi);
        bins[static_cast<std::size_t>(turns * kNematicBins) % kNematicBins].push_back(b);
    }
    for (std::size_t k = 0; k < bins.size(); ++k)
        fill_batches(cr, painter, bodies, bins[k], outline,
                     k + 1 == bins.size() ? kMediumFill
                                          : nematic_colour((static_cast<double>(k) + 0.5) *
                                                           std::numbers::pi / kNematicBins));
    return std::any_of(bins.begin(), bins.end() - 1, [](const auto& bin) { return !bin.empty(); });
}

// DBSCAN labels of the polar rods, renumbered by flock size. DBSCAN numbers flocks by where it
// met them first, which changes from frame to frame; ranked by size (largest first, the label
// order as tie-break) a flock keeps its colour through a movie as long as it stays the n-th
// largest. `flocks` receives their number.
std::vector<int> flocks_by_size(const BodyState& bodies, const std::vector<std::size_t>& polar,
                                const PeriodicBox2D& box, const DbscanParameters& parameters,
                                int& flocks) {
    std::vector<Vec3> centres;
    for (std::size_t b : polar)
        centres.push_back(bodies.position[b]);
    std::vector<int> labels = dbscan(centres, box, parameters);
    flocks = 0;
    for (int l : labels)
        flocks = std::max(flocks, l + 1);
    std::vector<int> size(static_cast<std::size_t>(flocks), 0), rank(size.size());
    for (int l : labels)
        if (l >= 0) ++size[static_cast<std::size_t>(l)];
    std::vector<int> by_size(size.size());
    for (std::size_t l = 0; l < by_size.size(); ++l)
        by_size[l] = static_cast<int>(l);
    std::stable_sort(by_size.begin(), by_size.end(), [&](int a, int b) {
        return size[static_cast<std::size_t>(a)] > size[static_cast<std::size_t>(b)];
    });
    for (std::size_t r = 0; r < by_size.size(); ++r)
        rank[static_cast<std::size_t>(by_size[r])] = static_cast<int>(r);
    for (int& l : labels)
        if (l >= 0) l = rank[static_cast<std::size_t>(l)];
    return labels;
}

// Polar rods one by one, lowest first, each in the colour `colour_of(index in polar)` gives.
template <class ColourOf>
void draw_polar(cairo_t* cr, const DiscPainter& painter, const BodyState& bodies,
                const std::vector<std::size_t>& polar, double outline, ColourOf colour_of) {
    std::vector<std::size_t> order(polar.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return bodies.position[polar[a]].z < bodies.position[polar[b]].z;
    });
    for (std::size_t i : order) {
        const std::size_t b = polar[i];
        if (outline > 0.0) {
            cairo_new_path(cr);
            painter.add(bodies, b, 0.0);
            set_colour(cr, kOutline);
            cairo_fill(cr);
        }
        cairo_new_path(cr);
        painter.add(bodies, b, outline);
        set_colour(cr, colour_of(i));
        cairo_fill(cr);
    }
}

// Calls `draw(x, y)` at (x, y) and at its periodic images one box away: a glyph near an edge
// shows on both sides, as bodies do; the clip keeps what is outside the view.
template <class Draw>
void at_images(const Box& box, double x, double y, Draw draw) {
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
            draw(x + i * box.lx, y + j * box.ly);
}

constexpr Rgb kDirector{0.10, 0.10, 0.45};
constexpr Rgb kPlusHalf{0.85, 0.05, 0.05};
constexpr Rgb kMinusHalf{0.05, 0.25, 0.85};
constexpr Rgb kFullDefect{0.45, 0.05, 0.55};

void draw_overlay(cairo_t* cr, const OverlayShapes& shapes, double pixels_per_mm, const Box& box) {
    const double px = 1.0 / pixels_per_mm, c = shapes.cell;
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    if (!shapes.director.empty()) {
        set_colour(cr, kDirector);
        cairo_set_line_width(cr, std::max(1.0 * px, 0.06 * c));
        cairo_new_path(cr);
        for (const OverlayShapes::Stick& s : shapes.director) {
            const double hx = 0.5 * s.length * std::cos(s.angle),
                         hy = 0.5 * s.length * std::sin(s.angle);
            at_images(box, s.x, s.y, [&](double x, double y) {
                cairo_move_to(cr, x - hx, y - hy);
                cairo_line_to(cr, x + hx, y + hy);
            });
        }
        cairo_stroke(cr);
    }
    const double line = std::max(1.5 * px, 0.08 * c);
    for (const NematicDefect& d : shapes.defects) {
        at_images(box, d.x, d.y, [&](double x, double y) {
            cairo_new_path(cr);
            cairo_set_line_width(cr, line);
            if (d.charge == 0.5) {
                // The comet: its head at the core, its tail along the orientation.
                set_colour(cr, kPlusHalf);
                cairo_arc(cr, x, y, 0.22 * c, 0.0, 2.0 * std::numbers::pi);
                cairo_fill(cr);
                cairo_move_to(cr, x, y);
                cairo_line_to(cr, x + 0.8 * c * std::cos(d.orientation),
                              y + 0.8 * c * std::sin(d.orientation));
                cairo_stroke(cr);
            } else if (d.charge == -0.5) {
                set_colour(cr, kMinusHalf);
                for (int k = 0; k < 3; ++k) {
                    const double a = std::numbers::pi / 2.0 + k * 2.0 * std::numbers::pi / 3.0;
                    cairo_move_to(cr, x, y);
                    cairo_line_to(cr, x + 0.45 * c * std::cos(a), y + 0.45 * c * std::sin(a));
                }
                cairo_stroke(cr);
            } else {
                set_colour(cr, kFullDefect);
                cairo_arc(cr, x, y, 0.35 * c, 0.0, 2.0 * std::numbers::pi);
                cairo_stroke(cr);
            }
        });
    }
    for (const OverlayShapes::Trail& t : shapes.trails) {
        set_colour(cr, label_colour(t.track));
        cairo_set_line_width(cr, std::max(2.0 * px, 0.1 * c));
        // Each step is the minimum image of the centre's displacement, so a path that crosses
        // the box edge leaves one side and enters the other.
        for (std::size_t k = 1; k < t.centres.size(); ++k) {
            const Vec3 &a = t.centres[k - 1], &b = t.centres[k];
            const double dx = std::remainder(b.x - a.x, box.lx),
                         dy = std::remainder(b.y - a.y, box.ly);
            at_images(box, a.x, a.y, [&](double x, double y) {
                cairo_move_to(cr, x, y);
                cairo_line_to(cr, x + dx, y + dy);
            });
        }
        cairo_stroke(cr);
        const Vec3& now = t.centres.back();
        const double ax = shapes.arrow * std::cos(t.heading),
                     ay = shapes.arrow * std::sin(t.heading);
        at_images(box, now.x, now.y, [&](double x, double y) {
            cairo_move_to(cr, x, y);
            cairo_line_to(cr, x + ax, y + ay);
            // The head: two barbs at ±150° from the arrow.
            for (const double turn : {2.6, -2.6}) {
                const double h = t.heading + turn;
                cairo_move_to(cr, x + ax, y + ay);
                cairo_line_to(cr, x + ax + 0.3 * shapes.arrow * std::cos(h),
                              y + ay + 0.3 * shapes.arrow * std::sin(h));
            }
        });
        cairo_stroke(cr);
        at_images(box, t.leader.x, t.leader.y, [&](double x, double y) {
            cairo_new_sub_path(cr);
            cairo_arc(cr, x, y, 0.3 * shapes.arrow, 0.0, 2.0 * std::numbers::pi);
        });
        cairo_stroke(cr);
    }
}

}  // namespace

FrameRenderer::FrameRenderer(const RunPlan& plan, const RenderOptions& options)
    : plan_(plan), options_(options) {
    const double lx = plan.engine.box.lx, ly = plan.engine.box.ly;
    if (options.width < 64 || options.width > 16384)
        throw InvalidParameter("--size", std::to_string(options.width) + " px", "[64, 16384] px");
    region_ = options.region.value_or(ViewRegion{0.0, lx, 0.0, ly});
    const ViewRegion& r = region_;
    if (!(r.x0 >= 0.0 && r.x0 < r.x1 && r.x1 <= lx && r.y0 >= 0.0 && r.y0 < r.y1 && r.y1 <= ly))
        throw InvalidParameter("--region",
                               format_number(r.x0) + "," + format_number(r.x1) + "," +
                                   format_number(r.y0) + "," + format_number(r.y1) + " mm",
                               "X0,X1,Y0,Y1 with 0 <= X0 < X1 <= " + format_number(lx) +
                                   " and 0 <= Y0 < Y1 <= " + format_number(ly) + " mm (the box)");
    width_ = options.width;
    scale_ = static_cast<double>(width_) / (r.x1 - r.x0);
    height_ = std::max(2, 2 * static_cast<int>(std::lround(0.5 * scale_ * (r.y1 - r.y0))));
    if (height_ > 16384)
        throw InvalidParameter("--size", std::to_string(options.width) + " px",
                               "a width that keeps the height within 16384 px",
                               "this view would be " + std::to_string(height_) + " px high");

    double polar_length = 0.0;
    for (const Species& s : plan.engine.species)
        if (is_polar(s)) polar_length = std::max(polar_length, s.shape.extent);
    flocks_.eps = options.flock_eps.value_or(0.5 * polar_length);
    flocks_.min_samples = options.flock_min_samples;
    if (options.polar == PolarColouring::flock) {
        if (polar_length == 0.0)
            throw InvalidParameter("--colour", "flock", "direction or uniform",
                                   "the run has no polar rods to group into flocks");
        if (!(flocks_.eps > 0.0 && flocks_.eps <= 0.5 * std::min(lx, ly)))
            throw InvalidParameter("--flock-eps", format_number(flocks_.eps) + " mm",
                                   "(0, " + format_number(0.5 * std::min(lx, ly)) + "] mm");
    }
    if (options.overlay.any()) overlay_ = std::make_unique<OverlayBuilder>(plan, options.overlay);
    if (options.annotate) {
        top_ = header_height(width_, static_cast<int>(annotation_lines().size()));
        bottom_ = footer_height(width_, legend_wheels());
        bottom_ += (top_ + bottom_) % 2;  // H.264 needs an even height
        height_ += top_ + bottom_;
        if (height_ > 16384)
            throw InvalidParameter(
                "--size", std::to_string(options.width) + " px",
                "a width that keeps the height within 16384 px",
                "this view and its annotations would be " + std::to_string(height_) + " px high");
    }
}

std::vector<std::string> FrameRenderer::annotation_lines() const {
    std::vector<std::string> lines{"t"};  // the time line, per frame
    const double area = plan_.engine.box.lx * plan_.engine.box.ly;
    for (std::uint32_t s = 0; s < plan_.engine.species.size(); ++s) {
        const Species& sp = plan_.engine.species[s];
        lines.push_back(
            sp.name + ": " + std::to_string(plan_.counts[s]) + " " + plural_kind(sp.kind) +
            ", φ = " +
            fixed(static_cast<double>(plan_.counts[s]) * sp.shape.projected_area / area, 3));
    }
    if (options_.polar == PolarColouring::flock)
        lines.push_back("colour: flock (DBSCAN ε = " + format_number(flocks_.eps) + " mm)");
    if (overlay_)
        for (std::string& line : overlay_->caption())
            lines.push_back(std::move(line));
    if (options_.region)
        lines.push_back("view: x " + format_number(region_.x0) + "–" + format_number(region_.x1) +
                        " mm, y " + format_number(region_.y0) + "–" + format_number(region_.y1) +
                        " mm");
    return lines;
}

bool FrameRenderer::legend_wheels() const {
    bool polar = false, rods = false;
    for (std::size_t s = 0; s < plan_.engine.species.size(); ++s) {
        polar = polar || (is_polar(plan_.engine.species[s]) && plan_.counts[s] > 0);
        rods =
            rods || (plan_.engine.species[s].kind == BodyKind::apolar_rod && plan_.counts[s] > 0);
    }
    return (polar && options_.polar == PolarColouring::direction) ||
           (rods && options_.medium == MediumColouring::nematic);
}

void FrameRenderer::remember(const BodyState& bodies, double time) const {
    if (overlay_) overlay_->update(bodies, time);
}

Image FrameRenderer::render(const BodyState& bodies, const FrameLabel& label) const {
    Image image;
    render_into(bodies, label, image);
    return image;
}

void FrameRenderer::render_into(const BodyState& bodies, const FrameLabel& label,
                                Image& image) const {
    image.width = width_;
    image.height = height_;
    image.pixels.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0);
    cairo_surface_t* surface =
        cairo_image_surface_create_for_data(reinterpret_cast<unsigned char*>(image.pixels.data()),
                                            CAIRO_FORMAT_ARGB32, width_, height_, width_ * 4);
    cairo_t* cr = cairo_create(surface);
    set_colour(cr, kBackground);
    cairo_paint(cr);

    // World (mm, y up) to pixels.
    cairo_matrix_t world;
    cairo_matrix_init(&world, scale_, 0.0, 0.0, -scale_, -region_.x0 * scale_,
                      region_.y1 * scale_ + top_);
    cairo_set_matrix(cr, &world);
    // Bodies stay inside the view: a periodic image past its edge must not spill into the
    // annotation strips.
    cairo_rectangle(cr, region_.x0, region_.y0, region_.x1 - region_.x0, region_.y1 - region_.y0);
    cairo_clip(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_set_tolerance(cr, 0.3);
    // Not CAIRO_ANTIALIAS_FAST: its scan converter (tor22) overflows a heap buffer on some paths
    // in Cairo 1.16 (seen under valgrind on the largest system; mplcairo issue #13).

    // An outline one pixel wide inside each body's true edge, where the smallest sphere is big
    // enough on screen to keep some colour inside it; otherwise plain fills.
    double smallest_radius = 1e300;
    for (const Species& s : plan_.engine.species)
        for (double r : s.shape.radii)
            smallest_radius = std::min(smallest_radius, r);
    const double outline = smallest_radius * scale_ >= 2.5 ? 1.0 / scale_ : 0.0;
    const DiscPainter painter(cr, plan_, region_, scale_);

    std::vector<std::size_t> polar, medium;
    for (std::size_t b = 0; b < bodies.size(); ++b)
        (is_polar(plan_.engine.species[bodies.species[b]]) ? polar : medium).push_back(b);
    const bool nematic = options_.medium == MediumColouring::nematic;
    const bool medium_axes = draw_medium(cr, painter, plan_, bodies, medium, outline, nematic);
    std::vector<double> angles;
    for (std::size_t b : polar)
        angles.push_back(in_plane_angle(bodies.orientation[b]));
    std::vector<int> labels;
    int flocks = 0;
    if (options_.polar == PolarColouring::flock && !polar.empty())
        labels = flocks_by_size(bodies, polar, {plan_.engine.box.lx, plan_.engine.box.ly}, flocks_,
                                flocks);
    draw_polar(cr, painter, bodies, polar, outline, [&](std::size_t i) {
        return options_.polar == PolarColouring::direction ? direction_colour(angles[i])
               : options_.polar == PolarColouring::flock   ? label_colour(labels[i])
                                                           : kPolarUniform;
    });

    if (overlay_) draw_overlay(cr, overlay_->update(bodies, label.time), scale_, plan_.engine.box);
    cairo_reset_clip(cr);
    if (options_.annotate)
        annotate(
            cr, bodies, label,
            {flocks, !polar.empty() && options_.polar == PolarColouring::direction, medium_axes});

    const cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    cairo_surface_flush(surface);
    cairo_surface_destroy(surface);
    // Cairo records errors (out of memory, a bad font) instead of throwing; a picture drawn
    // after one would be silently incomplete.
    if (status != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error(std::string("drawing the frame failed: ") +
                                 cairo_status_to_string(status));
}

void FrameRenderer::annotate(cairo_t* cr, const BodyState& bodies, const FrameLabel& label,
                             const Legend& legend) const {
    cairo_identity_matrix(cr);
    const Annotator note(cr, width_, height_);
    // The view's upper and lower edges, drawn in the strips' last and first rows.
    set_colour(cr, {0.6, 0.6, 0.6});
    cairo_set_line_width(cr, 1.0);
    for (const double row : {top_ - 0.5, height_ - bottom_ + 0.5}) {
        cairo_move_to(cr, 0.0, row);
        cairo_line_to(cr, width_, row);
    }
    cairo_stroke(cr);
    std::vector<std::string> lines = annotation_lines();
    lines[0] = "t = " + fixed(label.time, 4) + " s   frame " + std::to_string(label.frame) +
               "   step " + std::to_string(label.step);
    for (std::uint32_t s = 0; s < plan_.engine.species.size(); ++s) {
        const BodyKind kind = plan_.engine.species[s].kind;
        if (kind == BodyKind::polar_rod)
            lines[1 + s] += ", P = " + fixed(orientational_order(bodies, s, 1), 2);
        else if (kind == BodyKind::apolar_rod)
            lines[1 + s] += ", S = " + fixed(orientational_order(bodies, s, 2), 2);
    }
    if (options_.polar == PolarColouring::flock)
        lines[1 + plan_.engine.species.size()] +=
            ", " + std::to_string(legend.flocks) + " flocks; grey: none";
    note.text_block(lines);
    note.scale_bar(scale_bar_length(region_.x1 - region_.x0), scale_);
    int slot = 0;
    if (legend.polar_wheel) note.wheel(slot++, "polar axis", direction_colour);
    if (legend.medium_wheel) note.wheel(slot, "medium axis", nematic_colour);
}

}  // namespace rodsea
