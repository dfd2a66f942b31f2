#include "rodsea/view/movie_command.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
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
#include "rodsea/view/panel_grid.hpp"

namespace rodsea {

const CommandSpec& movie_command_spec() {
    static const CommandSpec spec = [] {
        CommandSpec c{
            "movie",
            "RUN_DIR [RUN_DIR ...] [-o FILE.mp4] [--fps F] [--every K] [--from T] [--to T] "
            "[options]",
            "an H.264 movie of a run, or of several side by side (ffmpeg)",
            "A movie of a run (docs/visualisation.md): the frames drawn as by `rodsea render` and "
            "piped to ffmpeg (Debian's package), encoded as H.264 in an MP4 that browsers play. "
            "Several runs are laid out in a grid, each panel under its label, their frames in "
            "step: each movie frame shows every run at the same simulated time (the first run's "
            "frames, after --from, --to and --every, pick the times, which every other run must "
            "have), over the time all runs have. The file appears only when it is complete; Ctrl-C "
            "stops "
            "cleanly and leaves no partial movie.",
            {{"-o,--output", "FILE",
              "the MP4 to write (default RUN_DIR/movie.mp4; required for several runs)"},
             {"--labels", "L1,L2,..",
              "several runs: a label per panel (default: each run's last two path parts)"},
             {"--columns", "C", "several runs: panels per row (default: about the square root)"},
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
                                             "800; for several runs each panel's, default 480); "
                                             "the height follows the view"))
            c.options.push_back(std::move(o));
        return c;
    }();
    return spec;
}

namespace {

// "out/fig/runs/gamma=7/seed1/" → "gamma=7/seed1".
std::string default_label(const std::string& run_dir) {
    std::filesystem::path p = std::filesystem::path(run_dir).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
    const std::filesystem::path parent = p.parent_path().filename();
    return parent.empty() || parent == "." || parent == ".." ? p.filename().string()
                                                             : (parent / p.filename()).string();
}

// Cairo draws UTF-8 only; a label of other bytes would fail the first frame.
bool valid_utf8(const std::string& text) {
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        const std::size_t length = byte < 0x80           ? 1
                                   : (byte >> 5) == 0x6  ? 2
                                   : (byte >> 4) == 0xE  ? 3
                                   : (byte >> 3) == 0x1E ? 4
                                                         : 0;
        if (length == 0 || i + length > text.size()) return false;
        for (std::size_t k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return false;
        i += length;
    }
    return true;
}

std::vector<std::string> split_labels(const std::string& text) {
    std::vector<std::string> labels;
    std::string label;
    for (const char c : text) {
        if (c == ',') {
            labels.push_back(label);
            label.clear();
        } else {
            label += c;
        }
    }
    labels.push_back(label);
    return labels;
}

// The frame of `run` at time t, which must be there: frames in step show the same time.
std::size_t frame_at(const StoredRun& run, double t, const std::string& name) {
    const std::vector<double>& times = run.times();
    const auto it = std::lower_bound(times.begin(), times.end(), t);
    std::size_t k = static_cast<std::size_t>(it - times.begin());
    if (k == times.size() || (k > 0 && t - times[k - 1] < times[k] - t)) --k;
    const double spacing = times.size() > 1 ? times[1] - times[0] : 0.0;
    // Round-off of the frames' times (steps × dt) only.
    if (std::abs(times[k] - t) > 1e-6 * spacing + 1e-9)
        throw InvalidParameter("RUN_DIR", name,
                               "runs whose frames are in step with the first run's",
                               "it has no frame at t = " + format_number(t) + " s (nearest " +
                                   format_number(times[k]) +
                                   " s): give the run with the finest output.interval first, "
                                   "with --every to match the others");
    return k;
}

}  // namespace

int movie_command(const std::vector<std::string>& words, std::ostream& out, std::ostream&) {
    const std::optional<Arguments> parsed = arguments_or_help(words, movie_command_spec(), out);
    if (!parsed) return 0;
    const Arguments& args = *parsed;
    const std::size_t n = args.positional.size();
    if (n == 0)
        throw InvalidParameter("RUN_DIR", "none given",
                               "one run directory, or several side by side (rodsea movie --help)");
    if (n > 64) throw InvalidParameter("RUN_DIR", std::to_string(n) + " given", "at most 64 runs");
    const bool several = n > 1;
    for (const char* flag : {"--labels", "--columns"})
        if (!several && args.value(flag))
            throw InvalidParameter(flag, *args.value(flag),
                                   std::string(flag) + " with several runs");
    if (several && !args.value("--output"))
        throw InvalidParameter("--output", "missing", "the MP4 to write, for several runs");
    const RenderOptions options = render_options_from(args, several ? 480 : 800);
    if (options.width % 2 != 0)
        throw InvalidParameter("--size", std::to_string(options.width) + " px", "an even width",
                               "H.264 in yuv420p needs even sizes");
    VideoSettings video;
    video.fps = parse_number("--fps", args.value("--fps").value_or("20"), 1e-3, 120.0, "frames/s");
    video.crf = static_cast<int>(parse_count("--crf", args.value("--crf").value_or("20"), 0, 51));
    std::vector<std::string> labels;
    if (const auto given = args.value("--labels")) {
        labels = split_labels(*given);
        if (labels.size() != n)
            throw InvalidParameter("--labels", *given,
                                   "one label per run (" + std::to_string(n) + ")",
                                   "labels are separated by commas");
    } else {
        for (const std::string& p : args.positional)
            labels.push_back(default_label(p));
    }
    for (std::size_t i = 0; i < labels.size(); ++i)
        if (!valid_utf8(labels[i]))
            throw InvalidParameter(
                args.value("--labels") ? "--labels" : "RUN_DIR",
                args.value("--labels") ? "label " + std::to_string(i + 1) : args.positional[i],
                "labels in UTF-8 text", args.value("--labels") ? "" : "give --labels");
    const int columns = static_cast<int>(
        args.value("--columns")
            ? parse_count("--columns", *args.value("--columns"), 1, static_cast<long long>(n))
            : static_cast<long long>(std::ceil(std::sqrt(static_cast<double>(n)) - 1e-9)));

    // Every run is opened and checked before anything is drawn; renderers keep a reference to
    // their run's plan, so the runs do not move once opened.
    std::vector<std::unique_ptr<StoredRun>> runs;
    for (const std::string& p : args.positional)
        runs.push_back(std::make_unique<StoredRun>(open_stored_run(p)));
    const StoredRun& run = *runs.front();
    std::vector<std::size_t> frames = frame_window_from(args, run);
    const std::vector<double>& times = run.times();
    // Only the times every run has.
    double last = times[frames.back()];
    for (const auto& r : runs)
        last = std::min(last, r->times().back() + 1e-9);
    double first = times[frames.front()];
    for (const auto& r : runs)
        first = std::max(first, r->times().front() - 1e-9);
    std::erase_if(frames, [&](std::size_t k) { return times[k] < first || times[k] > last; });
    if (frames.empty())
        throw InvalidParameter("RUN_DIR", args.positional.back(),
                               "runs whose times overlap those chosen from the first run");
    std::vector<std::vector<std::size_t>> frame_of(n);
    for (std::size_t i = 0; i < n; ++i)
        for (const std::size_t k : frames)
            frame_of[i].push_back(i == 0 ? k : frame_at(*runs[i], times[k], args.positional[i]));

    const std::filesystem::path output =
        args.value("--output").value_or((run.run_dir / "movie.mp4").string());
    check_output_file("--output", output, ".mp4");
    std::vector<std::unique_ptr<FrameRenderer>> renderers;
    std::vector<std::pair<int, int>> sizes;
    for (const auto& r : runs) {
        renderers.push_back(std::make_unique<FrameRenderer>(r->plan, options));
        sizes.emplace_back(renderers.back()->width(), renderers.back()->height());
    }
    const std::optional<PanelGrid> grid =
        several ? std::optional<PanelGrid>(PanelGrid(sizes, labels, columns)) : std::nullopt;
    video.width = grid ? grid->width() : renderers.front()->width();
    video.height = grid ? grid->height() : renderers.front()->height();
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
    if (!quiet) {
        std::size_t bodies = 0;
        for (const auto& r : runs)
            bodies += r->total_bodies();
        out << "rodsea movie " << (several ? std::to_string(n) + " runs" : run.run_dir.string())
            << ": " << frames.size() << " frames (t = " << format_number(times[frames.front()])
            << " to " << format_number(times[frames.back()]) << " s, every "
            << args.value("--every").value_or("1") << ") at " << format_number(video.fps)
            << " fps = " << format_number(static_cast<double>(frames.size()) / video.fps)
            << " s of video; " << bodies << " bodies; " << describe(options, *renderers.front());
        if (grid)
            out << "; " << grid->columns() << " × " << grid->rows() << " panels, " << video.width
                << " × " << video.height << " px";
        out << "\n"
            << "  H.264 (crf " << video.crf << ", yuv420p) by " << ffmpeg->string() << " → "
            << output.string() << "\n";
    }

    const auto start = std::chrono::steady_clock::now();
    const StopSignalGuard stop_guard;
    try {
        replace_file_atomically(output, [&](const std::filesystem::path& tmp) {
            FfmpegEncoder encoder(*ffmpeg, tmp, output, video, stop_signal_received);
            CountProgress progress(out, choose_progress_style(quiet, ::isatty(STDOUT_FILENO) == 1),
                                   frames.size(), "frames");
            std::vector<Image> panels(n);
            Image image;
            for (std::size_t f = 0; f < frames.size(); ++f) {
                if (const int signal = stop_signal_received()) throw StopRequested{signal};
                for (std::size_t i = 0; i < n; ++i) {
                    const std::size_t k = frame_of[i][f];
                    renderers[i]->render_into(runs[i]->frame(k),
                                              {runs[i]->times()[k], runs[i]->reader.steps()[k], k},
                                              several ? panels[i] : image);
                }
                if (grid) grid->compose(panels, image);
                encoder.write_frame(image);
                progress.update(f + 1);
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
