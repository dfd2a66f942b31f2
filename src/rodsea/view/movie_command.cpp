#include "rodsea/view/movie_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <ostream>

#include "rodsea/cli/count_progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/output_path.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/view/detail/ffmpeg_pipe.hpp"
#include "rodsea/view/detail/frame_flags.hpp"
#include "rodsea/view/detail/render_flags.hpp"

namespace rodsea {

const CommandSpec& movie_command_spec() {
    static const CommandSpec spec = [] {
        CommandSpec c{
            "movie",
            "RUN_DIR [-o FILE.mp4] [--fps F] [--every K] [--from T] [--to T] [options]",
            "an H.264 movie of a run (ffmpeg)",
            "A movie of a run (docs/visualisation.md): the frames drawn as by `rodsea render` and "
            "piped to ffmpeg (Debian's package), encoded as H.264 in an MP4 that browsers play. "
            "The file appears only when it is complete; Ctrl-C stops cleanly and leaves no "
            "partial movie.",
            {{"-o,--output", "FILE", "the MP4 to write (default RUN_DIR/movie.mp4)"},
             {"--fps", "F", "frames per second of the movie, [0.001, 120] (default 20)"},
             {"--every", "K", "use every K-th trajectory frame (default 1)"},
             {"--from", "T",
              "the start of the part of the run to show, s (default: the first frame)"},
             {"--to", "T", "its end, s (default: the last frame)"},
             {"--crf", "Q", "H.264 quality, 0 (lossless) … 51 (worst) (default 20)"},
             {"--quiet", "", "no plan and no progress bar"}},
            "Movies need even pixel sizes: --size must be even, and at most 4096 px wide and high "
            "so that browsers' H.264 decoders play them. Without ffmpeg the command exits with 1 "
            "and says how to install it."};
        for (OptionSpec& o : picture_options("image width in pixels, even, [64, 16384] (default "
                                             "800); the height follows the view"))
            c.options.push_back(std::move(o));
        return c;
    }();
    return spec;
}

int movie_command(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    const std::optional<Arguments> parsed = arguments_or_help(words, movie_command_spec(), out);
    if (!parsed) return 0;
    const Arguments& args = *parsed;
    if (args.positional.size() != 1)
        throw InvalidParameter("RUN_DIR", std::to_string(args.positional.size()) + " given",
                               "exactly one run directory (see rodsea movie --help)");
    const RenderOptions options = render_options_from(args, 800);
    if (options.width % 2 != 0)
        throw InvalidParameter("--size", std::to_string(options.width) + " px", "an even width",
                               "H.264 in yuv420p needs even sizes");
    VideoSettings video;
    video.fps = parse_number("--fps", args.value("--fps").value_or("20"), 1e-3, 120.0, "frames/s");
    video.crf = static_cast<int>(parse_count("--crf", args.value("--crf").value_or("20"), 0, 51));
    const StoredRun run = open_stored_run(args.positional[0]);
    const std::vector<std::size_t> frames = frame_window_from(args, run);
    const std::filesystem::path output =
        args.value("--output").value_or((run.run_dir / "movie.mp4").string());
    check_output_file("--output", output, ".mp4");
    const FrameRenderer renderer(run.plan, options);
    video.width = renderer.width();
    video.height = renderer.height();
    // Level 5.1, what browsers decode in hardware, stops at 4096 × 2304; software decoders in
    // browsers take 4096 in both directions.
    if (video.width > 4096 || video.height > 4096)
        throw InvalidParameter("--size", std::to_string(options.width) + " px",
                               "a size that keeps the movie within 4096 × 4096 px",
                               "this view would be " + std::to_string(video.width) + " × " +
                                   std::to_string(video.height) + " px");
    const std::optional<std::filesystem::path> ffmpeg = find_ffmpeg();
    if (!ffmpeg)
        throw std::runtime_error(
            std::getenv("RODSEA_FFMPEG")
                ? "ffmpeg not found: RODSEA_FFMPEG=" + std::string(std::getenv("RODSEA_FFMPEG")) +
                      " is not an executable file"
                : "ffmpeg not found on PATH; install Debian's ffmpeg package: "
                  "./scripts/install-deps.sh");

    const bool quiet = args.has("--quiet");
    const std::vector<double>& times = run.times();
    if (!quiet)
        out << "rodsea movie " << run.run_dir.string() << ": " << frames.size()
            << " frames (t = " << format_number(times[frames.front()]) << " to "
            << format_number(times[frames.back()]) << " s, every "
            << args.value("--every").value_or("1") << ") at " << format_number(video.fps)
            << " fps = " << format_number(static_cast<double>(frames.size()) / video.fps)
            << " s of video; " << run.total_bodies() << " bodies; " << describe(options, renderer)
            << "\n"
            << "  H.264 (crf " << video.crf << ", yuv420p) by " << ffmpeg->string() << " → "
            << output.string() << "\n";

    const auto start = std::chrono::steady_clock::now();
    const StopSignalGuard stop_guard;
    try {
        replace_file_atomically(output, [&](const std::filesystem::path& tmp) {
            FfmpegEncoder encoder(*ffmpeg, tmp, output, video, stop_signal_received);
            CountProgress progress(out, choose_progress_style(quiet, ::isatty(STDOUT_FILENO) == 1),
                                   frames.size(), "frames");
            Image image;
            for (std::size_t i = 0; i < frames.size(); ++i) {
                if (const int signal = stop_signal_received()) throw StopRequested{signal};
                const std::size_t k = frames[i];
                renderer.render_into(run.frame(k), {times[k], run.reader.steps()[k], k}, image);
                encoder.write_frame(image);
                progress.update(i + 1);
            }
            encoder.finish();
            progress.finish();
        });
    } catch (const StopRequested& stop) {
        out << "\nrodsea movie: stopped by signal " << stop.signal << "; no movie written\n";
        return stop.exit_code();
    }
    if (!quiet) report_written(out, output, start);
    return 0;
}

}  // namespace rodsea
