#include "rodsea/view/render_command.hpp"

#include <chrono>
#include <optional>
#include <ostream>

#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/output_path.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/view/detail/frame_flags.hpp"
#include "rodsea/view/detail/render_flags.hpp"
#include "rodsea/view/png_file.hpp"

namespace rodsea {

const CommandSpec& render_command_spec() {
    static const CommandSpec spec = [] {
        CommandSpec c{
            "render",
            "RUN_DIR [--frame N | --time T] [-o FILE.png] [options]",
            "a top view of one frame",
            "A top view of one frame of a run (docs/visualisation.md): every body drawn as "
            "its true outline (the union of its spheres), polar rods coloured by the "
            "direction of their axis, the medium in grey, the time, area fractions and "
            "order parameters in a corner, a scale bar in mm and a colour legend. Bodies "
            "that cross the box edge appear on both sides (the box is periodic).",
            {{"--frame", "N",
              "frame index, 0-based; negative counts from the end (default -1, the "
              "last)"},
             {"--time", "T", "the frame nearest T, s"},
             {"-o,--output", "FILE", "the PNG to write (default RUN_DIR/frame_<N>.png)"},
             {"--quiet", "", "no plan line and no timing"}},
            ""};
        for (OptionSpec& o : picture_options("image width in pixels, [64, 16384] (default 1200); "
                                             "the height follows the view"))
            c.options.push_back(std::move(o));
        return c;
    }();
    return spec;
}

namespace {

std::string frame_name(std::size_t frame) {
    std::string digits = std::to_string(frame);
    return "frame_" + std::string(digits.size() < 6 ? 6 - digits.size() : 0, '0') + digits + ".png";
}

}  // namespace

int render_command(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    const std::optional<Arguments> parsed = arguments_or_help(words, render_command_spec(), out);
    if (!parsed) return 0;
    const Arguments& args = *parsed;
    if (args.positional.size() != 1)
        throw InvalidParameter("RUN_DIR", std::to_string(args.positional.size()) + " given",
                               "exactly one run directory (see rodsea render --help)");
    const RenderOptions options = render_options_from(args, 1200);
    const StoredRun run = open_stored_run(args.positional[0]);
    const std::size_t index = single_frame_from(args, run).value_or(run.frames() - 1);
    const std::filesystem::path output =
        args.value("--output").value_or((run.run_dir / frame_name(index)).string());
    check_output_file("--output", output, ".png");
    const FrameRenderer renderer(run.plan, options);
    const bool quiet = args.has("--quiet");
    if (!quiet)
        out << "rodsea render " << run.run_dir.string() << ": frame " << index << " of 0–"
            << run.frames() - 1 << " (t = " << format_number(run.times()[index]) << " s), "
            << run.total_bodies() << " bodies; " << describe(options, renderer) << "\n";

    const auto start = std::chrono::steady_clock::now();
    // Flock tracks need the frames of the trail before this one.
    if (options.overlay.flock_tracks) {
        const double from = run.times()[index] - options.overlay.trail;
        for (std::size_t k = 0; k < index; ++k)
            if (run.times()[k] >= from - 1e-9) renderer.remember(run.frame(k), run.times()[k]);
    }
    // Ctrl-C while drawing stops before anything is written; once the PNG is being written it
    // is finished (a fraction of a second), so that no half-written file is ever left.
    const StopSignalGuard stop_guard;
    const Image image =
        renderer.render(run.frame(index), {run.times()[index], run.reader.steps()[index], index});
    if (const int signal = stop_signal_received()) {
        out << "rodsea render: stopped by signal " << signal << "; nothing written\n";
        return StopRequested{signal}.exit_code();
    }
    write_png(image, output);
    if (!quiet) report_written(out, output, start);
    return 0;
}

}  // namespace rodsea
