// Cost of each observable on one frame of the paper's largest system (L = 252 mm, 101070 beads
// at φ = 0.80 + 800 polar rods at φ_p = 0.05: 101870 bodies), as `rodsea analyze` runs it: the
// frame read from HDF5, the analysis frame, the shared grids, each observable's compute(), and
// the once-per-run finish of C(t) over 1000 frames. Sum of the per-frame figures × 1000 frames
// = the whole analysis of a 1000-frame trajectory.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

#include "rodsea/analysis/coarse_grained_fields.hpp"
#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analysis/flock_tracks.hpp"
#include "rodsea/analysis/nematic_defects.hpp"
#include "rodsea/analyze/analysis_frame.hpp"
#include "rodsea/analyze/autocorrelation_observable.hpp"
#include "rodsea/analyze/frame_context.hpp"
#include "rodsea/analyze/observable_registry.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace {

using namespace rodsea;

// The analysis' view of a 252 mm system: its species with their counts and area fractions, a
// frame every 0.05 s, 1000 steady frames.
AnalysisSetup setup_of(const EngineParameters& params, const std::vector<long long>& counts) {
    AnalysisSetup setup;
    setup.box = {252.0, 252.0};
    for (std::size_t s = 0; s < counts.size(); ++s)
        setup.species.push_back({params.species[s].name, params.species[s].kind,
                                 params.species[s].shape.extent, counts[s],
                                 static_cast<double>(counts[s]) *
                                     params.species[s].shape.projected_area / (252.0 * 252.0)});
    setup.frame_interval = 0.05;
    setup.steady_frames = 1000;
    return setup;
}

struct LargestSystem {
    EngineParameters params;
    BodyState bodies;
    AnalysisFrame frame;
    AnalysisSetup setup;
    AnalysisOptions options;
    std::filesystem::path trajectory;

    LargestSystem() {
        params.box = {252.0, 252.0};
        params.species = {polar_rod_species(), bead_species()};
        params.species[0].name = "polar";
        params.species[1].name = "medium";
        const std::vector<long long> counts{
            count_for_area_fraction(0.05, params.box, params.species[0].shape),
            count_for_area_fraction(0.80, params.box, params.species[1].shape)};
        bodies = build_initial_state(params, counts, {}, 1);
        SplitMix64 rng(2);
        for (Vec3& v : bodies.velocity)  // granular-gas-like in-plane velocities, mm/s
            v = {rng.uniform(-20, 20), rng.uniform(-20, 20), 0.0};
        frame = make_analysis_frame(bodies, {252.0, 252.0}, 0, 0.0, 0);
        setup = setup_of(params, counts);
        options = resolve_analysis_options({}, setup);
        trajectory = std::filesystem::temp_directory_path() / "rodsea-bench-analysis.h5";
        TrajectoryFile file = TrajectoryFile::create(trajectory, params, bodies.species, "", {});
        file.append_frame(0, 0.0, bodies, {});
    }
    ~LargestSystem() { std::filesystem::remove(trajectory); }

    std::vector<double> angles() const {  // every body's in-plane angle, rad
        std::vector<double> a;
        for (const Quat& q : bodies.orientation)
            a.push_back(in_plane_angle(q));
        return a;
    }
};

LargestSystem& largest() {
    static LargestSystem system;
    return system;
}

void BM_ReadFrame(benchmark::State& state) {
    const TrajectoryReader reader(largest().trajectory);
    for (auto _ : state) {
        const BodyState b = reader.frame(0);
        benchmark::DoNotOptimize(b.position.data());
    }
    state.counters["bodies"] = static_cast<double>(largest().bodies.size());
}
BENCHMARK(BM_ReadFrame)->Unit(benchmark::kMillisecond);

void BM_AnalysisFrame(benchmark::State& state) {
    for (auto _ : state) {
        const AnalysisFrame f = make_analysis_frame(largest().bodies, {252.0, 252.0}, 0, 0.0, 0);
        benchmark::DoNotOptimize(f.theta.data());
    }
}
BENCHMARK(BM_AnalysisFrame)->Unit(benchmark::kMillisecond);

void BM_SharedGrids(benchmark::State& state) {
    for (auto _ : state) {
        const FrameContext context(largest().frame, largest().setup.species, true);
        for (BodyGroup g : {BodyGroup::polar, BodyGroup::medium})
            benchmark::DoNotOptimize(context.group(g).members.data());
    }
}
BENCHMARK(BM_SharedGrids)->Unit(benchmark::kMillisecond);

// compute() of one observable on the frame; the grids are built outside the timing, as they
// are shared by all observables of a frame.
void BM_Observable(benchmark::State& state, const char* name) {
    LargestSystem& s = largest();
    const std::unique_ptr<Observable> observable = make_observable(name, s.setup, s.options);
    const FrameContext context(s.frame, s.setup.species, true);
    for (BodyGroup g : {BodyGroup::polar, BodyGroup::medium, BodyGroup::medium_rods})
        context.group(g);
    for (auto _ : state)
        observable->compute(context);
}
BENCHMARK_CAPTURE(BM_Observable, order, "order")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Observable, pair, "pair")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Observable, corotating, "corotating")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Observable, autocorrelation, "autocorrelation")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Observable, flocks, "flocks")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Observable, segregation, "segregation")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Observable, bands, "bands")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Observable, medium_velocity, "medium_velocity")->Unit(benchmark::kMillisecond);

// The beyond-paper observables on the same frame. Fields: all 101870 bodies on cells of 2 mm (126 ×
// 126), area fraction, polarisation, Q and velocity.
void BM_CoarseGrainedFields(benchmark::State& state) {
    const LargestSystem& s = largest();
    const std::vector<double> angles = s.angles();
    const PeriodicBox2D box{252.0, 252.0};
    const FieldGrid grid = FieldGrid::of(box, 2.0);
    for (auto _ : state)
        benchmark::DoNotOptimize(
            coarse_grain(grid, box, s.bodies.position, angles, s.bodies.velocity, 0.5).weight);
    state.counters["cells"] = static_cast<double>(grid.cells());
}
BENCHMARK(BM_CoarseGrainedFields)->Unit(benchmark::kMillisecond);

// Defects of the beads' (disordered) director field: every plaquette is looked at, and many
// hold a defect: the worst case.
void BM_NematicDefects(benchmark::State& state) {
    const LargestSystem& s = largest();
    const std::vector<double> angles = s.angles();
    const PeriodicBox2D box{252.0, 252.0};
    const FieldGrid grid = FieldGrid::of(box, 2.0);
    const GroupFields f = coarse_grain(grid, box, s.bodies.position, angles, {}, 0.5);
    std::size_t found = 0;
    for (auto _ : state)
        found = find_nematic_defects(grid, f.qxx, f.qxy).size();
    state.counters["defects"] = static_cast<double>(found);
}
BENCHMARK(BM_NematicDefects)->Unit(benchmark::kMillisecond);

// Linking one frame's flocks of the 800 polar rods to the previous frame's (DBSCAN itself is the
// `flocks` observable above).
void BM_FlockTracking(benchmark::State& state) {
    const LargestSystem& s = largest();
    std::vector<Vec3> rods;
    std::vector<double> angles;
    for (std::size_t b = 0; b < s.bodies.size(); ++b)
        if (s.bodies.species[b] == 0) {
            rods.push_back(s.bodies.position[b]);
            angles.push_back(in_plane_angle(s.bodies.orientation[b]));
        }
    const PeriodicBox2D box{252.0, 252.0};
    const std::vector<int> labels = dbscan(rods, box, {.eps = 2.25, .min_samples = 3});
    FlockTracker tracker(box);
    double t = 0.0;
    for (auto _ : state)
        tracker.add_frame(t += 0.05, labels, rods, angles);
    state.counters["rods"] = static_cast<double>(rods.size());
}
BENCHMARK(BM_FlockTracking)->Unit(benchmark::kMillisecond);

// The paper's largest system of rods: 800 polar rods at φ_p = 0.05 and apolar rods of ℓ_a =
// 2.5 mm at φ_a = 0.80 (L = 252 mm). The medium's angles are drawn at random (an isotropic
// medium, as the paper's at σ = 3.125): its director field is disordered and full of defects,
// the worst case for the defect search and tracking.
struct RodSystem {
    AnalysisFrame frame;
    AnalysisSetup setup;
    AnalysisOptions options;

    RodSystem() {
        EngineParameters params;
        params.box = {252.0, 252.0};
        params.species = {polar_rod_species(), apolar_rod_species(2.5)};
        params.species[0].name = "polar";
        params.species[1].name = "medium";
        const std::vector<long long> counts{
            count_for_area_fraction(0.05, params.box, params.species[0].shape),
            count_for_area_fraction(0.80, params.box, params.species[1].shape)};
        const BodyState bodies = build_initial_state(params, counts, {}, 1);
        frame = make_analysis_frame(bodies, {252.0, 252.0}, 0, 0.0, 0);
        SplitMix64 rng(3);
        for (std::size_t b = 0; b < frame.size(); ++b) {
            frame.velocity[b] = {rng.uniform(-20, 20), rng.uniform(-20, 20), 0.0};
            if (frame.species[b] == 1) frame.theta[b] = rng.uniform(-3.14159, 3.14159);
        }
        setup = setup_of(params, counts);
        options = resolve_analysis_options({}, setup);
    }
};

RodSystem& rods() {
    static RodSystem system;
    return system;
}

// compute() of one of the beyond-paper observables on a fresh frame each time, because they share
// the frame's fields, defects and flock labels (FrameContext), which the first of them builds:
// that cost is counted here, the group arrays (shared with every observable) are not. On the
// rod system (defects need apolar rods) and, for those that apply, the 101870-body bead system.
template <class System>
void BM_FieldObservable(benchmark::State& state, System& (*system)(), const char* name) {
    System& s = system();
    AnalysisSetup setup = s.setup;
    setup.frames = 1000;
    const std::unique_ptr<Observable> observable = make_observable(name, setup, s.options);
    AnalysisFrame frame = s.frame;
    int k = 0;
    for (auto _ : state) {
        state.PauseTiming();
        frame.time = 0.05 * ++k;  // trackers need later and later frames
        const FrameContext context(frame, setup.species, true);
        for (BodyGroup g : {BodyGroup::polar, BodyGroup::medium, BodyGroup::medium_rods})
            context.group(g);
        state.ResumeTiming();
        observable->compute(context);
    }
    state.counters["bodies"] = static_cast<double>(frame.size());
}
BENCHMARK_CAPTURE(BM_FieldObservable, rods_fields, &rods, "fields")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FieldObservable, rods_defects, &rods, "defects")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FieldObservable, rods_flocks, &rods, "flocks")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FieldObservable, rods_flock_defects, &rods, "flock_defects")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FieldObservable, beads_fields, &largest, "fields")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FieldObservable, beads_flocks, &largest, "flocks")
    ->Unit(benchmark::kMillisecond);

// The once-per-run part of C(t): 800 polar rods over 1000 frames, FFT per rod, 4 blocks.
void BM_AutocorrelationFinish(benchmark::State& state) {
    LargestSystem& s = largest();
    for (auto _ : state) {
        state.PauseTiming();
        AutocorrelationObservable o(s.setup, s.options);
        const FrameContext context(s.frame, s.setup.species, true);
        for (int k = 0; k < 1000; ++k)
            o.compute(context);
        state.ResumeTiming();
        benchmark::DoNotOptimize(o.finish().scalars.data());
    }
}
BENCHMARK(BM_AutocorrelationFinish)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
