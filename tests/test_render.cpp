// `rodsea render` on frames placed by hand: each body's colour lands on the pixels of its true
// outline, at the place the box coordinates say, across the periodic edge too; the colour maps
// are periodic where the angles are; bad input is refused and leaves no file.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <set>
#include <tuple>

#include "child_process.hpp"
#include "constructed_run.hpp"
#include "defect_fields.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/view/colour_wheel.hpp"
#include "rodsea/view/png_file.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;
constexpr double kBox = 20.0;  // mm

RunPlan polar_rods(int count) {
    return load_config_string("[box]\nside = " + std::to_string(kBox) +
                                  "\n[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\n"
                                  "count = " +
                                  std::to_string(count) + "\n",
                              "test");
}

struct Pixel {
    int r = 0, g = 0, b = 0;
};

Pixel pixel_at(const Image& image, int column, int row) {
    const std::uint32_t p = image.at(column, row);
    return {static_cast<int>(p >> 16 & 0xff), static_cast<int>(p >> 8 & 0xff),
            static_cast<int>(p & 0xff)};
}

// The pixel under the point (x, y) mm of a view [x0, x1] × [y0, y1] drawn `width` pixels wide:
// columns grow with x, rows grow downwards from y1.
Pixel pixel_under(const Image& image, double x, double y, double x0 = 0.0, double x1 = kBox,
                  double y1 = kBox) {
    const double s = static_cast<double>(image.width) / (x1 - x0);
    return pixel_at(image, static_cast<int>(std::floor((x - x0) * s)),
                    static_cast<int>(std::floor((y1 - y) * s)));
}

// 8-bit rounding of the expected colour is the only difference allowed inside a body: its
// interior is fully covered, so antialiasing does not touch it.
void expect_colour(const Pixel& p, const Rgb& c, const std::string& where) {
    EXPECT_NEAR(p.r, c.r * 255.0, 1.0) << where;
    EXPECT_NEAR(p.g, c.g * 255.0, 1.0) << where;
    EXPECT_NEAR(p.b, c.b * 255.0, 1.0) << where;
}

void expect_background(const Pixel& p, const std::string& where) {
    EXPECT_EQ(p.r, 255) << where;
    EXPECT_EQ(p.g, 255) << where;
    EXPECT_EQ(p.b, 255) << where;
}

class RenderCli : public ::testing::Test {
  protected:
    void SetUp() override { scratch_ = std::make_unique<ScratchDir>("render"); }
    fs::path path(const std::string& name) const { return scratch_->path() / name; }

    // Writes a one-frame run of polar rods at (x, y, θ) and renders it.
    Image render(const std::vector<std::array<double, 3>>& rods,
                 const std::vector<std::string>& extra = {}) {
        const RunPlan plan = polar_rods(static_cast<int>(rods.size()));
        BodyState frame;
        for (const auto& [x, y, theta] : rods)
            add_flat_body(frame, plan, 0, x, y, theta);
        write_constructed_run(path("run"), plan, {frame}, 0.01);
        std::vector<std::string> args{
            "render", path("run").string(), "-o", path("out.png").string(), "--size", "400"};
        args.insert(args.end(), extra.begin(), extra.end());
        const ChildResult r = run_rodsea(args, scratch_->path());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_png(path("out.png"));
    }

    // Renders the last frame of an existing run `width` pixels wide without annotations.
    Image render_bare(const fs::path& run, int width, const std::vector<std::string>& extra) {
        std::vector<std::string> args{"render",
                                      run.string(),
                                      "-o",
                                      path("bare.png").string(),
                                      "--size",
                                      std::to_string(width),
                                      "--no-annotations"};
        args.insert(args.end(), extra.begin(), extra.end());
        const ChildResult r = run_rodsea(args, scratch_->path());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return read_png(path("bare.png"));
    }

    std::unique_ptr<ScratchDir> scratch_;
};

TEST_F(RenderCli, RodColourAtItsCentreAndBackgroundOutsideItsOutline) {
    const double theta = 2.0;  // rad: a colour far from the wheel's red start
    const Image image = render({{8.0, 11.0, theta}}, {"--no-annotations"});
    ASSERT_EQ(image.width, 400);
    ASSERT_EQ(image.height, 400);  // square box
    expect_colour(pixel_under(image, 8.0, 11.0), direction_colour(theta), "centre of mass");

    const RunPlan plan = polar_rods(1);
    const Shape& shape = plan.engine.species[0].shape;
    const double c = std::cos(theta), s = std::sin(theta);
    // Beside the axis, 0.3 mm beyond the widest sphere; and 0.3 mm beyond each end.
    const double side = shape.max_radius + 0.3;
    expect_background(pixel_under(image, 8.0 - side * s, 11.0 + side * c), "beside the rod");
    expect_background(pixel_under(image, 8.0 + side * s, 11.0 - side * c), "other side");
    for (std::size_t k : {std::size_t{0}, shape.sphere_count() - 1}) {
        const Vec3& o = shape.offsets[k];
        const double out = (std::abs(o.x) + shape.radii[k] + 0.3) / std::abs(o.x);
        expect_background(pixel_under(image, 8.0 + out * o.x * c, 11.0 + out * o.x * s),
                          "beyond end sphere " + std::to_string(k));
        // ... and the end sphere's own centre is the rod's colour: the whole outline is drawn.
        expect_colour(pixel_under(image, 8.0 + o.x * c, 11.0 + o.x * s), direction_colour(theta),
                      "end sphere " + std::to_string(k));
    }
}

TEST_F(RenderCli, RodAcrossThePeriodicEdgeAppearsOnBothSides) {
    // Axis along +x with the centre 0.4 mm from the left edge: the spheres behind the centre lie
    // at x < 0 and must appear at x + L, the right edge of the picture.
    const Image image = render({{0.4, 10.0, 0.0}}, {"--no-annotations"});
    const Shape& shape = polar_rods(1).engine.species[0].shape;
    int wrapped = 0, inside = 0;
    for (std::size_t k = 0; k < shape.sphere_count(); ++k) {
        const double x = 0.4 + shape.offsets[k].x;
        if (std::abs(x) < 0.1) continue;  // too close to the edge to say which side
        const double shown = x < 0.0 ? x + kBox : x;
        (x < 0.0 ? wrapped : inside)++;
        expect_colour(pixel_under(image, shown, 10.0), direction_colour(0.0),
                      "sphere " + std::to_string(k) + " at x = " + std::to_string(x));
    }
    EXPECT_GT(wrapped, 0);
    EXPECT_GT(inside, 0);
    // Nothing is drawn where no image of the rod reaches, e.g. mid-box at the same height.
    expect_background(pixel_under(image, 10.0, 10.0), "mid-box");
}

TEST_F(RenderCli, RodAcrossTheCornerWrapsInBothDirections) {
    // Centre 0.3 mm from the top and right edges, axis at 45°: the thin end crosses both edges.
    const double theta = std::numbers::pi / 4, cx = kBox - 0.3, cy = kBox - 0.3;
    const Image image = render({{cx, cy, theta}}, {"--no-annotations"});
    const Shape& shape = polar_rods(1).engine.species[0].shape;
    std::set<std::pair<bool, bool>> quadrants;
    for (std::size_t k = 0; k < shape.sphere_count(); ++k) {
        const double x = cx + shape.offsets[k].x * std::cos(theta);
        const double y = cy + shape.offsets[k].x * std::sin(theta);
        if (std::abs(x - kBox) < 0.1 || std::abs(y - kBox) < 0.1) continue;  // on an edge
        const double wx = x >= kBox ? x - kBox : x, wy = y >= kBox ? y - kBox : y;
        quadrants.insert({x >= kBox, y >= kBox});
        expect_colour(pixel_under(image, wx, wy), direction_colour(theta),
                      "sphere " + std::to_string(k));
    }
    EXPECT_EQ(quadrants.size(), 2u);  // spheres inside the box and spheres past the corner
    expect_background(pixel_under(image, 10.0, 10.0), "mid-box");
    expect_background(pixel_under(image, 1.5, 18.5), "top-left corner, away from every image");
}

TEST_F(RenderCli, NematicColoursIgnoreWhichEndIsWhich) {
    // Two apolar rods at θ and θ + π get one colour; a third at θ + π/2 the opposite hue.
    const RunPlan plan = load_config_string(
        "[box]\nside = 20.0\n[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\n"
        "length = 2.5\ncount = 3\n",
        "test");
    const double theta = 0.4;
    BodyState frame;
    add_flat_body(frame, plan, 0, 5.0, 5.0, theta);
    add_flat_body(frame, plan, 0, 15.0, 5.0, theta + kPi);
    add_flat_body(frame, plan, 0, 10.0, 15.0, theta + kPi / 2);
    write_constructed_run(path("apolar"), plan, {frame}, 0.01);
    for (const std::string medium : {"nematic", "neutral"}) {
        const ChildResult r =
            run_rodsea({"render", path("apolar").string(), "-o", path("n.png").string(), "--size",
                        "400", "--medium", medium, "--no-annotations"},
                       scratch_->path());
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const Image image = read_png(path("n.png"));
        const Pixel a = pixel_under(image, 5.0, 5.0), b = pixel_under(image, 15.0, 5.0),
                    c = pixel_under(image, 10.0, 15.0);
        EXPECT_EQ(std::tie(a.r, a.g, a.b), std::tie(b.r, b.g, b.b)) << medium;
        if (medium == "neutral") {
            EXPECT_EQ(std::tie(a.r, a.g, a.b), std::tie(c.r, c.g, c.b));
            continue;
        }
        // Colours are drawn in 2° bins: within a bin the wheel at 2θ moves by at most ~6 of 255.
        const Rgb expected = nematic_colour(theta);
        EXPECT_NEAR(a.r, expected.r * 255.0, 8.0);
        EXPECT_NEAR(a.g, expected.g * 255.0, 8.0);
        EXPECT_NEAR(a.b, expected.b * 255.0, 8.0);
        EXPECT_GT(std::abs(a.r - c.r) + std::abs(a.g - c.g) + std::abs(a.b - c.b), 200);
    }
}

// Medium rods, one at the centre of each 2.6 mm cell, their axes following a ± defect pair
// summed over periodic images (so exactly two defects on the torus), drawn with --overlay
// defects on cells of 2.6 mm: the red comet sits at the +1/2, the blue trefoil at the −1/2.
TEST_F(RenderCli, DefectOverlayMarksThePlantedDefects) {
    const int n = 10;
    const double side = 2.6 * n, xp = 7.8, xm = 18.2, y0 = 13.0;  // cores inside plaquettes
    const RunPlan plan = load_config_string(
        "[box]\nside = " + std::to_string(side) +
            "\n[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\nlength = 2.5\ncount = " +
            std::to_string(n * n) + "\n",
        "test");
    BodyState frame;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = 2.6 * (i + 0.5), y = 2.6 * (j + 0.5);
            add_flat_body(frame, plan, 0, x, y, testing::pair_angle(x, y, xp, xm, y0, side));
        }
    write_constructed_run(path("pair"), plan, {frame}, 0.01);
    const auto draw = [&](const std::vector<std::string>& extra) {
        return render_bare(path("pair"), 520, extra);
    };
    // Pixels of a glyph's colour (the medium is grey, the background white): their farthest
    // distance from a core, in mm.
    const auto farthest = [&](const Image& image, auto is_colour, double cx, double cy) {
        const double mm = side / image.width;
        double far = -1.0;
        for (int row = 0; row < image.height; ++row)
            for (int col = 0; col < image.width; ++col) {
                const Pixel p = pixel_at(image, col, row);
                if (!is_colour(p)) continue;
                const double dx = std::remainder((col + 0.5) * mm - cx, side),
                             dy = std::remainder(side - (row + 0.5) * mm - cy, side);
                far = std::max(far, std::hypot(dx, dy));
            }
        return far;
    };
    const auto red = [](const Pixel& p) { return p.r > 180 && p.g < 80 && p.b < 80; };
    const auto blue = [](const Pixel& p) { return p.b > 180 && p.r < 80 && p.g < 120; };
    const Image plain = draw({});
    EXPECT_LT(farthest(plain, red, xp, y0), 0.0) << "red without an overlay";
    EXPECT_LT(farthest(plain, blue, xm, y0), 0.0) << "blue without an overlay";
    const Image marked = draw({"--overlay", "defects", "--overlay-cell", "2.6"});
    // The core is refined within its plaquette (half a cell diagonal, 1.8 mm), the comet's tail
    // reaches 0.8 cell beyond it and the trefoil's arms 0.45 cell: all within 4.2 mm.
    const double red_reach = farthest(marked, red, xp, y0);
    const double blue_reach = farthest(marked, blue, xm, y0);
    EXPECT_GT(red_reach, 0.0);
    EXPECT_LT(red_reach, 1.8 + 0.8 * 2.6);
    EXPECT_GT(blue_reach, 0.0);
    EXPECT_LT(blue_reach, 1.8 + 0.45 * 2.6);
}

// A flock of five rods side by side, heading +x, moving 3 mm per frame for four frames: its
// track's path (drawn from the frames before the one rendered) crosses where the flock was
// and no rod is now, in the colour of track 0.
TEST_F(RenderCli, FlockTrackOverlayDrawsThePathOfTheFlock) {
    const RunPlan plan = polar_rods(5);
    std::vector<BodyState> frames(4);
    for (int k = 0; k < 4; ++k)
        for (int r = 0; r < 5; ++r)
            add_flat_body(frames[static_cast<std::size_t>(k)], plan, 0, 4.0 + 3.0 * k,
                          8.2 + 0.9 * r, 0.0);
    write_constructed_run(path("moving"), plan, frames, 0.01);
    const auto draw = [&](const std::vector<std::string>& extra) {
        return render_bare(path("moving"), 400, extra);
    };
    // (7, 10): the flock's centre one frame after the start, 6 mm behind it now (its rods reach
    // 2.25 mm behind their centres).
    expect_background(pixel_under(draw({}), 7.0, 10.0), "without the overlay");
    expect_colour(pixel_under(draw({"--overlay", "flock-tracks"}), 7.0, 10.0), label_colour(0),
                  "on the path");
    // A trail shorter than one frame interval leaves only the present.
    expect_background(
        pixel_under(draw({"--overlay", "flock-tracks", "--trail", "0.005"}), 7.0, 10.0),
        "with a trail of 5 ms");
}

// The same flock crossing the periodic edge (x = 15, 18, 21 ≡ 1, 24 ≡ 4 mm): its path leaves on
// the right and enters on the left, with no stroke across the box.
TEST_F(RenderCli, FlockTrackCrossesThePeriodicEdge) {
    const RunPlan plan = polar_rods(5);
    std::vector<BodyState> frames(4);
    for (int k = 0; k < 4; ++k)
        for (int r = 0; r < 5; ++r)
            add_flat_body(frames[static_cast<std::size_t>(k)], plan, 0,
                          std::fmod(15.0 + 3.0 * k, kBox), 8.2 + 0.9 * r, 0.0);
    write_constructed_run(path("crossing"), plan, frames, 0.01);
    const Image image = render_bare(path("crossing"), 400, {"--overlay", "flock-tracks"});
    expect_colour(pixel_under(image, 19.6, 10.0), label_colour(0), "before the edge");
    expect_colour(pixel_under(image, 0.3, 10.0), label_colour(0), "after the edge");
    // Where a stroke from x = 18 back to x = 1 would pass, before the path starts (x = 15) and
    // beyond the heading arrow's tip (x = 4 + 1.5 ℓ_p = 10.75).
    expect_background(pixel_under(image, 13.0, 10.0), "inside the box, off the path");
}

TEST_F(RenderCli, ZoomMapsTheRegionOntoTheWholeImage) {
    // The view x ∈ [5, 15], y ∈ [8, 13] mm: 400 × 200 px, 40 px/mm.
    const Image image =
        render({{9.0, 10.0, kPi / 2}}, {"--no-annotations", "--region", "5,15,8,13"});
    ASSERT_EQ(image.width, 400);
    ASSERT_EQ(image.height, 200);
    expect_colour(pixel_under(image, 9.0, 10.0, 5.0, 15.0, 13.0), direction_colour(kPi / 2),
                  "rod centre in the zoomed view");
    expect_background(pixel_under(image, 11.0, 10.0, 5.0, 15.0, 13.0), "2 mm to its right");
}

TEST_F(RenderCli, FlockColouringSeparatesAFlockFromALoner) {
    // Three parallel rods 1 mm apart form a DBSCAN cluster (ε = ℓ_p/2 = 2.25 mm, 3 samples);
    // a fourth rod 8 mm away is noise.
    const Image image =
        render({{5.0, 5.0, 0.0}, {5.0, 6.0, 0.0}, {5.0, 7.0, 0.0}, {15.0, 15.0, 0.0}},
               {"--no-annotations", "--colour", "flock"});
    for (double y : {5.0, 6.0, 7.0})
        expect_colour(pixel_under(image, 5.0, y), label_colour(0), "flock member");
    expect_colour(pixel_under(image, 15.0, 15.0), label_colour(-1), "loner");
}

TEST_F(RenderCli, FlockColoursGoByFlockSize) {
    // DBSCAN meets the three-rod flock first (lowest index), but the four-rod flock is larger:
    // it gets the first colour.
    const Image image = render({{4.0, 4.0, 0.0},
                                {4.0, 5.0, 0.0},
                                {4.0, 6.0, 0.0},
                                {14.0, 12.0, 0.0},
                                {14.0, 13.0, 0.0},
                                {14.0, 14.0, 0.0},
                                {14.0, 15.0, 0.0}},
                               {"--no-annotations", "--colour", "flock"});
    for (double y : {4.0, 5.0, 6.0})
        expect_colour(pixel_under(image, 4.0, y), label_colour(1), "the smaller flock");
    for (double y : {12.0, 13.0, 14.0, 15.0})
        expect_colour(pixel_under(image, 14.0, y), label_colour(0), "the larger flock");
}

TEST_F(RenderCli, AnnotationsLieOutsideTheViewAndHideNoBody) {
    // Rods in all four corners, where the text, the scale bar and the colour wheel used to sit
    // on top of the bodies: with annotations the picture of the box must appear whole, pixel for
    // pixel the picture without them, between a strip of text above and one of legends below.
    const std::vector<std::array<double, 3>> rods{
        {2.5, 18.0, 0.3}, {17.5, 18.0, 1.3}, {2.5, 1.5, 2.3}, {17.5, 1.5, 3.3}};
    const Image bare = render(rods, {"--no-annotations"});
    const Image annotated = render(rods);
    ASSERT_EQ(annotated.width, bare.width);
    ASSERT_GT(annotated.height, bare.height);
    int offset = -1;
    for (int top = 0; top + bare.height <= annotated.height && offset < 0; ++top) {
        bool same = true;
        for (int row = 0; row < bare.height && same; ++row)
            for (int col = 0; col < bare.width && same; ++col)
                same = annotated.at(col, top + row) == bare.at(col, row);
        if (same) offset = top;
    }
    EXPECT_GT(offset, 0) << "the view is not in the annotated picture unchanged";
    EXPECT_LT(offset + bare.height, annotated.height) << "no strip below the view";
}

TEST_F(RenderCli, ScaleBarIsAsLongAsItSays) {
    // 400 px for 20 mm: the bar is the largest 1/2/5 × 10^k mm within a fifth of the width, so
    // 2 mm = 40 px; it is the longest black run of pixels in the bottom rows.
    const Image image = render({{10.0, 10.0, 0.0}});
    int longest = 0;
    for (int row = image.height - 40; row < image.height; ++row) {
        int run = 0;
        for (int col = 0; col < image.width / 2; ++col) {
            const Pixel p = pixel_at(image, col, row);
            run = (p.r + p.g + p.b < 30) ? run + 1 : 0;
            longest = std::max(longest, run);
        }
    }
    EXPECT_NEAR(longest, 40, 1);
}

TEST_F(RenderCli, BadInputIsRefusedAndWritesNothing) {
    render({{10.0, 10.0, 0.0}});
    fs::remove(path("out.png"));
    struct Case {
        std::vector<std::string> args;
        int exit_code;
        std::string message;
    };
    const std::string run = path("run").string(), png = path("out.png").string();
    const std::vector<Case> cases{
        {{"render", run, "--frame", "3", "-o", png}, 2, "--frame"},
        {{"render", run, "--time", "5", "-o", png}, 2, "--time"},
        {{"render", run, "--colour", "rainbow", "-o", png}, 2, "direction, flock or uniform"},
        {{"render", run, "--medium", "pink", "-o", png}, 2, "neutral or nematic"},
        {{"render", run, "--region", "5,25,0,10", "-o", png}, 2, "--region"},
        {{"render", run, "--size", "10", "-o", png}, 2, "--size"},
        {{"render", run, "-o", path("out.jpg").string()}, 2, ".png"},
        {{"render", run, "-o", (path("no-such-dir") / "x.png").string()}, 74, "does not exist"},
        {{"render", path("missing").string(), "-o", png}, 74, "no such file"},
        {{"render", run, "--colr", "flock", "-o", png}, 2, "--colr"},
        {{"render", run, "--overlay", "vortices", "-o", png}, 2, "defects, director, flock"},
        {{"render", run, "--overlay", "defects", "-o", png}, 2, "no apolar rods"},
        {{"render", run, "--trail", "3", "-o", png}, 2, "only with --overlay"},
        {{"render", run, "--overlay", "flock-tracks", "--overlay-cell", "15", "-o", png},
         2,
         "--overlay-cell"},
    };
    for (const Case& c : cases) {
        const ChildResult r = run_rodsea(c.args, scratch_->path());
        EXPECT_EQ(r.exit_code, c.exit_code) << c.args[2] << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    // Nothing but the run and the captured output in the scratch directory.
    for (const auto& entry : fs::directory_iterator(scratch_->path()))
        EXPECT_TRUE(entry.path().filename() == "run" ||
                    entry.path().filename().string().rfind("child.", 0) == 0)
            << entry.path();
}

}  // namespace
}  // namespace rodsea
