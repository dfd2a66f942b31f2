// Cost of a snapshot of the paper's largest system (examples/largest.toml: L = 252 mm, 101 070
// beads at φ = 0.80 + 800 polar rods at φ_p = 0.05), as `rodsea render` and `rodsea movie` pay
// it: drawing the frame with Cairo at several widths and each colouring, and encoding the PNG;
// and of a rod medium (examples/fig1-rods-vs-density.toml: 23 217 apolar rods of ℓ_a = 2.5 mm at
// φ_a = 0.5 + 800 polar rods, 219 353 spheres), neutral and coloured by nematic axis. Reading the
// frame from HDF5 is BM_ReadFrame in bench_analysis.cpp.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/view/frame_renderer.hpp"
#include "rodsea/view/png_file.hpp"

namespace {

using namespace rodsea;

struct Scene {
    explicit Scene(const char* config) : plan(load_config_file(config)) {}
    RunPlan plan;
    BodyState bodies = build_initial_state(plan.engine, plan.counts, plan.builder, 1);
};

const Scene& scene() {
    static const Scene s(RODSEA_SOURCE_DIR "/examples/largest.toml");
    return s;
}

const Scene& rod_medium() {
    static const Scene s(RODSEA_SOURCE_DIR "/examples/fig1-rods-vs-density.toml");
    return s;
}

void BM_RenderLargest(benchmark::State& state) {
    RenderOptions options;
    options.width = static_cast<int>(state.range(0));
    options.polar = static_cast<PolarColouring>(state.range(1));
    options.medium = static_cast<MediumColouring>(state.range(2));
    const FrameRenderer renderer(scene().plan, options);
    Image image;
    for (auto _ : state) {
        renderer.render_into(scene().bodies, {0.0, 0, 0}, image);
        benchmark::DoNotOptimize(image.pixels.data());
    }
    state.counters["bodies"] = static_cast<double>(scene().bodies.size());
}
// width px; polar colouring (0 direction, 1 flock); medium (0 neutral, 1 nematic)
BENCHMARK(BM_RenderLargest)
    ->Args({1000, 0, 0})
    ->Args({2000, 0, 0})
    ->Args({4000, 0, 0})
    ->Args({2000, 1, 0})
    ->Args({2000, 0, 1})
    ->Unit(benchmark::kMillisecond);

void BM_RenderRodMedium(benchmark::State& state) {
    RenderOptions options;
    options.width = 2000;
    options.medium = static_cast<MediumColouring>(state.range(0));
    const FrameRenderer renderer(rod_medium().plan, options);
    Image image;
    for (auto _ : state) {
        renderer.render_into(rod_medium().bodies, {0.0, 0, 0}, image);
        benchmark::DoNotOptimize(image.pixels.data());
    }
    state.counters["bodies"] = static_cast<double>(rod_medium().bodies.size());
}
// medium (0 neutral, 1 nematic)
BENCHMARK(BM_RenderRodMedium)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_WritePng(benchmark::State& state) {
    RenderOptions options;
    options.width = static_cast<int>(state.range(0));
    const Image image = FrameRenderer(scene().plan, options).render(scene().bodies, {0.0, 0, 0});
    const auto path = std::filesystem::temp_directory_path() / "rodsea-bench-render.png";
    for (auto _ : state)
        write_png(image, path);
    std::filesystem::remove(path);
}
BENCHMARK(BM_WritePng)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond);

}  // namespace
