// The beyond-paper observables of `rodsea analyze` on constructed frames whose
// answers geometry fixes: the interface of a polar stripe is two lines the box's height long,
// the coarse-grained maps conserve the area, a planted ± defect pair of the medium is found,
// counted and tracked, flocks that meet merge with their leader named by body index, and a
// flock sitting on a +1/2 defect moving along its orientation is seen as such.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <variant>

#include "analysis_frames.hpp"
#include "defect_fields.hpp"
#include "rodsea/analysis/contour_length.hpp"
#include "rodsea/analyze/defect_observable.hpp"
#include "rodsea/analyze/fields_observable.hpp"
#include "rodsea/analyze/flock_defect_observable.hpp"
#include "rodsea/analyze/flock_observable.hpp"
#include "rodsea/error.hpp"

namespace rodsea {
namespace {

using namespace rodsea::testing;
constexpr double kPi = std::numbers::pi;

const DatasetResult& dataset(const ObservableResults& r, const std::string& path) {
    for (const DatasetResult& d : r.datasets)
        if (d.path == path) return d;
    throw std::runtime_error("no dataset " + path);
}

template <class T>
const std::vector<T>& values(const ObservableResults& r, const std::string& path) {
    return std::get<std::vector<T>>(dataset(r, path).values);
}

// A straight level line crossing the whole periodic box is exactly as long as the box: linear
// interpolation puts every crossing on it. A disc's contour is a polygon inscribed in it, short
// by O((cell/R)²): 2 % at R = 5 cells.
TEST(LevelSet, AStripeHasTwoEdgesTheBoxLongAndADiscItsCircumference) {
    const PeriodicBox2D box{40.0, 30.0};
    const FieldGrid grid = FieldGrid::of(box, 2.0);
    std::vector<double> stripe(grid.cells()), disc(grid.cells());
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            const double x = (i + 0.5) * grid.dx, y = (j + 0.5) * grid.dy;
            stripe[grid.index(i, j)] = x > 10.0 && x < 20.0 ? 1.0 : 0.0;
            disc[grid.index(i, j)] = 10.0 - std::hypot(x - 21.0, y - 14.0);  // R = 10 mm
        }
    const LevelSet s = level_set(grid, stripe, 0.5);
    EXPECT_NEAR(s.length, 2.0 * box.ly, 1e-9);
    EXPECT_NEAR(s.above_fraction, 5.0 / 20.0, 1e-12);  // x = 11, 13, ..., 19 of 20 columns
    const LevelSet d = level_set(grid, disc, 0.0);
    EXPECT_NEAR(d.length, 2.0 * kPi * 10.0, 0.02 * 2.0 * kPi * 10.0);
    EXPECT_LT(d.length, 2.0 * kPi * 10.0);
    EXPECT_NEAR(d.above_fraction * 40.0 * 30.0, kPi * 100.0, 0.05 * kPi * 100.0);
}

// Polar rods fill a stripe of the box, the medium the rest, one body per mm² of equal area.
TEST(FieldsObservable, AStripeOfPolarRodsHasTwoInterfacesAndTheMapsConserveArea) {
    const double side = 40.0;
    std::vector<Body> bodies;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
            const double x = i + 0.5, y = j + 0.5;
            bodies.push_back({x, y, 0.3, x > 10.0 && x < 20.0 ? 0u : 1u});
        }
    AnalysisSetup setup = make_setup(side, bodies, 3);
    setup.frames = 3;
    // A body of 1 mm²: φ = count / box area.
    for (SpeciesInfo& s : setup.species)
        s.area_fraction = static_cast<double>(s.count) / (side * side);
    AnalysisOptions o;
    o.field_cell = 4.0;
    o.interface_level = 0.4;  // not 0.5: the cells on the stripe's edges hold exactly half
    FieldsObservable fields(setup, resolved(setup, o));
    const std::vector<AnalysisFrame> frames{
        make_frame(side, bodies, 0), make_frame(side, bodies, 1), make_frame(side, bodies, 2)};
    const ObservableResults r = run_on(fields, frames, setup);
    // The share of polar rods depends on x only: two straight edges the box's height long.
    EXPECT_NEAR(scalar(r, "interface_length").estimate.mean, 2.0 * side, 1e-9);
    EXPECT_NEAR(scalar(r, "interface_density").estimate.mean, 2.0 / side, 1e-12);
    // Cloud-in-cell weights sum to one per body: the mean of φ over the cells is the species'.
    for (const auto& [species, phi] : {std::pair{"polar", 400.0 / 1600.0}, {"medium", 0.75}}) {
        const auto& mean =
            values<double>(r, std::string("fields/mean/") + species + "/area_fraction");
        double sum = 0.0;
        for (double v : mean)
            sum += v;
        EXPECT_NEAR(sum / static_cast<double>(mean.size()), phi, 1e-12) << species;
        const auto& series =
            values<float>(r, std::string("fields/series/") + species + "/area_fraction");
        EXPECT_EQ(series.size(), 3 * mean.size());
    }
    // All rods at θ = 0.3: Q = (cos 0.6, sin 0.6) wherever there are rods.
    const auto& order = values<double>(r, "fields/mean/medium/S");
    const auto& director = values<double>(r, "fields/mean/medium/director");
    for (std::size_t c = 0; c < order.size(); ++c)
        if (!std::isnan(order[c])) {
            EXPECT_NEAR(order[c], 1.0, 1e-12);
            EXPECT_NEAR(director[c], 0.3, 1e-12);
        }
    for (double v : values<double>(r, "fields/mean/medium/qxx"))
        if (!std::isnan(v)) {
            EXPECT_NEAR(v, std::cos(0.6), 1e-12);
        }
}

TEST(FieldsObservable, MapsThatWouldNotFitInMemoryAreRefusedByKey) {
    AnalysisSetup setup = make_setup(1000.0, {{1.0, 1.0, 0.0, 0}, {2.0, 2.0, 0.0, 1}}, 100000);
    setup.frames = 100000;
    AnalysisOptions o;
    o.field_cell = 2.0;  // 500 × 500 cells, 12 maps, 10⁵ frames: 1.2 TB
    try {
        check_field_series_memory(setup, resolved(setup, o));
        FAIL() << "accepted";
    } catch (const InvalidParameter& e) {
        EXPECT_NE(std::string(e.what()).find("fields.every"), std::string::npos) << e.what();
    }
    o.field_every = 1000;
    EXPECT_NO_THROW(check_field_series_memory(setup, resolved(setup, o)));
}

TEST(FieldsObservable, DefaultRadiiFitABoxNarrowerThanTwoPolarRods) {
    // A 16 mm box (L/2 = 8 mm) is under 2 ℓ_p = 9 mm, the unclamped default of defects.pair: a
    // run this small must still be analysable for any observable, defects included, with the
    // radius cut to L/2 as every other automatic radius is; a value the user gives is not cut.
    const AnalysisSetup setup = make_setup(16.0, {{1.0, 1.0, 0.0, 0}, {2.0, 2.0, 0.0, 1}}, 1);
    const AnalysisOptions o = resolved(setup);
    EXPECT_EQ(o.field_cell, 4.5);
    EXPECT_EQ(o.defect_link, 4.5);
    EXPECT_EQ(o.defect_pair, 8.0);
    AnalysisOptions given;
    given.defect_pair = 9.0;
    try {
        resolved(setup, given);
        FAIL() << "accepted";
    } catch (const InvalidParameter& e) {
        EXPECT_NE(std::string(e.what()).find("defects.pair"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("L/2 = 8"), std::string::npos) << e.what();
    }
}

// Medium rods at the centres of 2 mm cells whose axes follow a ± pair summed over periodic
// images (periodic, so exactly two defects on the torus), the pair at (xp, y) and (xm, y).
std::vector<Body> medium_with_pair(double side, double xp, double xm, double y) {
    std::vector<Body> bodies;
    const int n = static_cast<int>(side / 2.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = 2.0 * i + 1.0, yy = 2.0 * j + 1.0;
            bodies.push_back({x, yy, pair_angle(x, yy, xp, xm, y, side), 1});
        }
    return bodies;
}

TEST(DefectObservable, APlantedPairIsCountedAndTrackedAsItMoves) {
    const double side = 32.0;
    std::vector<AnalysisFrame> frames;
    std::vector<Body> first;
    for (int k = 0; k < 3; ++k) {  // the pair drifts 0.5 mm per frame along x
        const std::vector<Body> b = medium_with_pair(side, 10.0 + 0.5 * k, 22.0 + 0.5 * k, 16.0);
        if (k == 0) first = b;
        frames.push_back(make_frame(side, b, static_cast<std::size_t>(k)));
    }
    AnalysisSetup setup = make_setup(side, first, frames.size());
    setup.frames = frames.size();
    AnalysisOptions o;
    o.field_cell = 2.0;
    DefectObservable defects(setup, resolved(setup, o));
    const ObservableResults r = run_on(defects, frames, setup);
    const TableResult& counts = table(r, "defect_counts");
    for (const auto& row : counts.rows) {
        EXPECT_EQ(row[column(counts, "plus_half")], 1.0);
        EXPECT_EQ(row[column(counts, "minus_half")], 1.0);
        EXPECT_EQ(row[column(counts, "total_charge")], 0.0);
    }
    // Two tracks of three frames each: moving 0.5 mm a frame is within defects.link (2 mm).
    const TableResult& tracks = table(r, "defect_tracks");
    ASSERT_EQ(tracks.rows.size(), 2u);
    for (const auto& row : tracks.rows) {
        EXPECT_EQ(row[column(tracks, "frames")], 3.0);
        // 0.5 mm per 0.01 s; the refined core wanders within its plaquette: within a cell.
        EXPECT_NEAR(row[column(tracks, "mean_speed")], 50.0, 100.0);
    }
    // The cores lie within a cell of the planted ones.
    const auto& x = values<double>(r, "defects/x");
    const auto& t = values<double>(r, "defects/time");
    const auto& q = values<std::int32_t>(r, "defects/twice_charge");
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double planted = (q[k] > 0 ? 10.0 : 22.0) + 0.5 * std::round(t[k] / 0.01);
        EXPECT_LT(std::abs(x[k] - planted), 2.0) << "charge " << q[k] / 2.0;
    }
    // The only events: the two defects appear in the first frame, 12 mm apart, farther than
    // defects.pair (4 mm): born alone, not created as a pair. Nothing dies or annihilates.
    const TableResult& events = table(r, "defect_events");
    ASSERT_EQ(events.rows.size(), 2u);
    for (const auto& row : events.rows) {
        EXPECT_EQ(row[column(events, "kind")], static_cast<double>(DefectEvent::Kind::birth));
        EXPECT_EQ(row[column(events, "time")], 0.0);
    }
}

TEST(FlockObservable, TwoFlocksMergeAndTheLeaderIsNamedByItsBodyIndex) {
    const double side = 60.0;
    std::vector<AnalysisFrame> frames;
    std::vector<Body> first;
    // Four medium rods first, so that polar rod k is body 4 + k. Flock A (rods 0–4) moves +x
    // at 1 mm per frame, flock B (rods 5–9) waits ahead of it; the gap between them closes
    // below DBSCAN's ε = ℓ_p / 2 = 2.25 mm in frame 3 (4.8 − 3 = 1.8 mm).
    for (int k = 0; k < 5; ++k) {
        std::vector<Body> b;
        for (int m = 0; m < 4; ++m)
            b.push_back({50.0, 10.0 * m + 5.0, 0.0, 1});
        for (int r = 0; r < 5; ++r)
            b.push_back({10.0 + k + 0.8 * r, 30.0, 0.0, 0});
        for (int r = 0; r < 5; ++r)
            b.push_back({18.0 + 0.8 * r, 30.0, 0.0, 0});
        if (k == 0) first = b;
        frames.push_back(make_frame(side, b, static_cast<std::size_t>(k)));
    }
    AnalysisSetup setup = make_setup(side, first, frames.size());
    setup.frames = frames.size();
    FlockObservable flocks(setup, resolved(setup));
    const ObservableResults r = run_on(flocks, frames, setup);
    const TableResult& events = table(r, "flock_events");
    bool merged = false;
    for (const auto& row : events.rows)
        merged =
            merged || row[column(events, "kind")] == static_cast<double>(FlockEvent::Kind::merge);
    EXPECT_TRUE(merged);
    // Flock A's first moving state: velocity 1 mm / 0.01 s along x, led by its front rod,
    // polar rod 4, body 8.
    const auto& track = values<std::int32_t>(r, "flock_tracks/track");
    const auto& vx = values<double>(r, "flock_tracks/vx");
    const auto& leader = values<std::int32_t>(r, "flock_tracks/leader");
    const auto& time = values<double>(r, "flock_tracks/time");
    bool seen = false;
    for (std::size_t k = 0; k < track.size(); ++k)
        if (track[k] == 0 && std::abs(time[k] - 0.01) < 1e-12) {
            EXPECT_NEAR(vx[k], 100.0, 1e-9);
            EXPECT_EQ(leader[k], 8);
            seen = true;
        }
    EXPECT_TRUE(seen);
}

// A flock of polar rods parked on the +1/2 defect of a planted pair, heading along the defect's
// orientation: it sits far nearer than a random point, and aligned.
TEST(FlockDefectObservable, AFlockOnAPlusHalfAlongItsOrientationIsNearAndAligned) {
    const double side = 32.0;
    std::vector<Body> bodies = medium_with_pair(side, 10.0, 22.0, 16.0);
    // The comet's orientation at the +1/2: the field there is ½ φ − ½ π (the −1/2 lies along
    // +x), the comet θ = ½ φ turned by −π, whose orientation is −π: the flock heads along −x.
    for (int r = 0; r < 5; ++r)
        bodies.push_back({9.0 + 0.5 * r, 16.0, kPi, 0});
    AnalysisSetup setup = make_setup(side, bodies, 1);
    setup.frames = 1;
    AnalysisOptions o;
    o.field_cell = 2.0;
    FlockDefectObservable observable(setup, resolved(setup, o));
    const ObservableResults r = run_on(observable, {make_frame(side, bodies)}, setup);
    // The flock's centre is within a cell of the core; a random point is ~L/4 from it.
    EXPECT_LT(scalar(r, "flock_defect_distance").estimate.mean, 2.0);
    EXPECT_GT(scalar(r, "random_defect_distance").estimate.mean, 6.0);
    EXPECT_LT(scalar(r, "defect_distance_ratio").estimate.mean, 0.3);
    // Orientations within 0.1 rad (test_nematic_fields) plus the plaquette's discretisation.
    EXPECT_GT(scalar(r, "flock_defect_alignment").estimate.mean, std::cos(0.3));
}

}  // namespace
}  // namespace rodsea
