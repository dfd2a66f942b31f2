#include "rodsea/view/export_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <string_view>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/cli/child_process.hpp"
#include "rodsea/cli/count_progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/output_path.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/view/detail/export_formats.hpp"
#include "rodsea/view/detail/frame_flags.hpp"
#include "rodsea/view/python_script.hpp"

namespace rodsea {

const CommandSpec& export_command_spec() {
    static const CommandSpec spec{
        "export",
        "RUN_DIR --format lammps-dump|xyz|gsd -o FILE [--frame N | --time T] [--every K] [--from "
        "T] "
        "[--to T] [--velocities] [--quiet]",
        "one particle per sphere, for VMD and OVITO",
        "Writes the run's frames as one particle per sphere, for VMD, OVITO and MDAnalysis "
        "(docs/export.md: the columns and the exact steps to open the file in each). Each sphere "
        "has an id, its body's id (molecule), its species (type, 1-based; the XYZ file names it), "
        "its radius and its body's orientation quaternion. Bodies are kept whole: the centre is "
        "wrapped into the box, spheres may stick out of [0, L) by less than a body length. Units: "
        "mm and s (times, and the velocities in mm/s); the box is [0, Lx] x [0, Ly] x "
        "[-A, w + A], the plates' whole travel. Everything is checked before anything is "
        "written; the file appears complete or not at all (also on a full disk or Ctrl-C).",
        {{"--format", "F",
          "lammps-dump: a LAMMPS custom dump (.lammpstrj; VMD, OVITO, MDAnalysis); xyz: extended "
          "XYZ (OVITO; MDAnalysis and other plain XYZ readers take the first four columns: "
          "species name, x, y, z); gsd: HOOMD's GSD, one particle per body with its quaternion "
          "and each species a SphereUnion shape (OVITO draws the rods; gsd.hoomd reads it), "
          "written with Debian's python3-gsd"},
         {"-o,--output", "FILE", "the file to write (replaced if it exists)"},
         {"--frame", "N", "one frame: 0-based, negative counts from the end (-1: the last)"},
         {"--time", "T", "one frame: the one nearest T, s"},
         {"--every", "K", "every K-th frame of the window (default 1: all)"},
         {"--from", "T", "the window's start, s (default: the first frame)"},
         {"--to", "T", "the window's end, s (default: the last frame)"},
         {"--velocities", "", "also the body centre's velocity (vx vy vz, mm/s)"},
         {"--quiet", "", "no plan and no progress lines"}},
        ""};
    return spec;
}

namespace {

namespace fs = std::filesystem;

// Concatenation by appending: GCC 12 at -O3 warns falsely (-Wrestrict) on "literal" + string.
std::string cat(std::initializer_list<std::string_view> parts) {
    std::string s;
    for (std::string_view p : parts)
        s.append(p);
    return s;
}

std::string megabytes(double bytes) {
    return cat({format_number(std::round(bytes / 1e4) / 100), " MB"});
}

ExportFormat format_from(const std::optional<std::string>& given) {
    std::string allowed;
    for (const std::string& n : export_format_names()) {
        if (!allowed.empty()) allowed += " or ";
        allowed += n;
    }
    if (!given) throw InvalidParameter("--format", "none given", allowed);
    if (const auto f = parse_export_format(*given)) return *f;
    const auto guess = config::closest_match(*given, export_format_names());
    std::string why;
    if (guess) {
        why = "did you mean '";
        why += *guess;
        why += "'?";
    }
    throw InvalidParameter("--format", quoted(*given), allowed, why);
}

// The frames the options select, in order: one (--frame, --time) or a window. Throws
// InvalidParameter naming the flag.
std::vector<std::size_t> select_frames(const StoredRun& run, const Arguments& a) {
    if (const std::optional<std::size_t> one = single_frame_from(a, run)) {
        for (const std::string& flag : kFrameWindowFlags)
            if (a.value(flag))
                throw InvalidParameter(flag, *a.value(flag), "without --frame and --time",
                                       "--frame and --time export a single frame");
        return {*one};
    }
    return frame_window_from(a, run);
}

// The output file can be written: its directory exists and is writable, it is not a
// directory, not the run's own trajectory, and the disk has room for it.
void check_output(const fs::path& path, const StoredRun& run, double bytes) {
    check_output_file("-o", path, "");
    std::error_code ec;
    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (fs::exists(path, ec)) {
        if (!fs::is_regular_file(path, ec))
            throw FileError(path.string(), "exists and is not a regular file");
        for (const fs::path& own : {run.trajectory, run.run_dir / "checkpoint.h5"})
            if (fs::exists(own, ec) && fs::equivalent(path, own, ec))
                throw InvalidParameter("-o", path.string(), "a file other than the run's own",
                                       cat({"it would replace ", own.string()}));
    }
    const fs::space_info space = fs::space(dir, ec);
    if (!ec && static_cast<double>(space.available) < bytes)
        throw FileError(path.string(),
                        cat({"needs about ", megabytes(bytes), ", but only ",
                             megabytes(static_cast<double>(space.available)), " are free"}));
}

// The extension VMD's reader for the format is registered under (plugins lammpstrj and xyz).
const char* extension_of(ExportFormat format) {
    return format == ExportFormat::lammps_dump ? "lammpstrj"
           : format == ExportFormat::xyz       ? "xyz"
                                               : "gsd";
}

bool extension_fits(const fs::path& path, ExportFormat format) {
    return path.extension() == std::string(".") + extension_of(format);
}

// What an export will write, checked and sized before anything is.
struct ExportJob {
    fs::path path;
    ExportOptions options;
    std::vector<std::size_t> frames;
    ExportScene scene;
    BodyState first;  // the first frame, read to check its bodies against the config
    std::size_t spheres = 0;
    double total_bytes = 0.0;
};

void print_plan(const ExportJob& job, const StoredRun& run, std::ostream& out) {
    const std::vector<double>& times = run.times();
    const std::vector<std::int64_t>& steps = run.reader.steps();
    const ExportScene& scene = job.scene;
    out << "export " << run.run_dir.string() << " -> " << job.path.string() << " ("
        << to_string(job.options.format) << (job.options.velocities ? ", with velocities" : "")
        << ")\n";
    if (job.frames.size() == 1)
        out << "  frame " << job.frames.front() << " of " << run.frames()
            << ": t = " << format_number(times[job.frames.front()]) << " s, step "
            << steps[job.frames.front()];
    else
        out << "  frames: " << job.frames.size() << " of " << run.frames()
            << ", t = " << format_number(times[job.frames.front()]) << " to "
            << format_number(times[job.frames.back()]) << " s";
    out << "\n  spheres per frame: " << job.spheres << " in " << job.first.size() << " bodies (";
    for (std::size_t s = 0; s < scene.species.size(); ++s)
        out << (s ? ", " : "") << "type " << s + 1 << " = " << scene.species[s].name << ": "
            << run.plan.counts[s] << " x " << scene.species[s].radii.size() << " spheres";
    out << ")\n  box: [0, " << format_number(scene.lx) << "] x [0, " << format_number(scene.ly)
        << "] x [" << format_number(scene.z_lo) << ", " << format_number(scene.z_hi)
        << "] mm; times in s (step x dt, dt = " << format_number(scene.dt)
        << " s)\n  estimated size: " << megabytes(job.total_bytes) << "\n";
    if (!extension_fits(job.path, job.options.format))
        out << "  note: VMD and OVITO pick their reader by extension; name the file ."
            << extension_of(job.options.format)
            << " or load it with an explicit type (docs/export.md)\n";
    out.flush();
}

// GSD through scripts/rodsea_gsd.py (gsd.hoomd, Debian's python3-gsd): every frame is read and
// checked here first (StoredRun::frame), then the script writes the temporary file.
void write_gsd(ExportJob& job, const StoredRun& run, std::ostream& out, std::ostream& err,
               bool quiet) {
    const PythonScriptLookup lookup =
        locate_python_script("rodsea_gsd.py", "python3, python3-gsd, python3-h5py");
    if (!lookup.found) throw FileError("rodsea_gsd.py", lookup.problem);
    CountProgress progress(out, choose_progress_style(quiet, ::isatty(STDOUT_FILENO) == 1),
                           job.frames.size(), "frames checked");
    for (std::size_t i = 1; i < job.frames.size(); ++i) {
        if (const int s = stop_signal_received()) throw StopRequested{s};
        run.frame(job.frames[i]);
        progress.update(i + 1);
    }
    progress.finish();
    const double height = job.scene.z_hi - job.scene.z_lo;
    replace_file_atomically(job.path, [&](const fs::path& tmp) {
        const fs::path list = tmp.string() + ".frames";
        {
            std::ofstream frames(list);
            for (std::size_t k : job.frames)
                frames << k << "\n";
            if (!frames) throw FileError(list.string(), "cannot write the frame list");
        }
        std::ostringstream script_out;
        const int code =
            run_program({lookup.found->python, "-B", lookup.found->script, run.trajectory.string(),
                         tmp.string(), list.string(), format_number(height)},
                        script_out, err, 1);
        std::error_code ec;
        fs::remove(list, ec);
        if (const int s = stop_signal_received()) throw StopRequested{s};
        if (code != 0)
            throw FileError(job.path.string(), "the GSD writer (" + lookup.found->script +
                                                   ") failed with exit code " +
                                                   std::to_string(code) + "; nothing written");
    });
}

// Writes every frame of the job into `path` atomically: the file appears complete or not at all,
// also on a full disk (FileError) or Ctrl-C (StopRequested).
void write_frames(ExportJob& job, const StoredRun& run, std::ostream& out, bool quiet) {
    const std::vector<double>& times = run.times();
    const std::vector<std::int64_t>& steps = run.reader.steps();
    replace_file_atomically(job.path, [&](const fs::path& tmp) {
        std::ofstream file(tmp, std::ios::binary | std::ios::trunc);
        if (!file) throw FileError(tmp.string(), cat({"cannot create: ", std::strerror(errno)}));
        CountProgress progress(out, choose_progress_style(quiet, ::isatty(STDOUT_FILENO) == 1),
                               job.frames.size(), "frames");
        for (std::size_t i = 0; i < job.frames.size(); ++i) {
            if (const int s = stop_signal_received()) throw StopRequested{s};
            const std::size_t k = job.frames[i];
            const BodyState frame = i == 0 ? std::move(job.first) : run.frame(k);
            write_export_frame(file, job.scene, job.options, frame, steps[k], times[k]);
            if (!file)
                throw FileError(job.path.string(),
                                cat({"write failed: ", std::strerror(errno),
                                     " (nothing written; the disk may be full)"}));
            progress.update(i + 1);
        }
        file.close();
        if (!file)
            throw FileError(job.path.string(),
                            cat({"write failed: ", std::strerror(errno), " (nothing written)"}));
        progress.finish();
    });
}

}  // namespace

int export_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const std::optional<Arguments> parsed = arguments_or_help(args, export_command_spec(), out);
    if (!parsed) return 0;
    const Arguments& a = *parsed;
    if (a.positional.empty())
        throw InvalidParameter("RUN_DIR", "none given",
                               "one run directory (see rodsea export --help)");
    if (a.positional.size() > 1)
        throw InvalidParameter("RUN_DIR", quoted(a.positional[1]), "exactly one run directory",
                               "export writes one run into one file");
    ExportJob job;
    job.options.format = format_from(a.value("--format"));
    job.options.velocities = a.has("--velocities");
    const bool quiet = a.has("--quiet");
    const std::optional<std::string> output = a.value("--output");
    if (!output || output->empty())
        throw InvalidParameter("-o", "none given", "the file to write, e.g. -o run.lammpstrj");
    job.path = *output;

    const StoredRun run = open_stored_run(a.positional[0]);
    job.frames = select_frames(run, a);
    job.scene = make_export_scene(run.plan);
    // The first frame is read now: its bodies must match the config before anything is
    // written. Every later frame is checked as it is read (StoredRun::frame).
    job.first = run.frame(job.frames.front());
    job.spheres = export_sphere_count(job.scene, job.first, run.trajectory.string());
    job.total_bytes = estimated_frame_bytes(job.scene, job.options, job.spheres, job.first.size()) *
                      static_cast<double>(job.frames.size());
    check_output(job.path, run, job.total_bytes);
    if (!quiet) print_plan(job, run, out);

    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    const StopSignalGuard signals;  // Ctrl-C stops between frames; a full disk fails a write
    try {
        if (job.options.format == ExportFormat::gsd)
            write_gsd(job, run, out, err, quiet);
        else
            write_frames(job, run, out, quiet);
    } catch (const StopRequested& stop) {
        err << "rodsea: export stopped by signal " << stop.signal << "; nothing written ("
            << job.path.string() << " is unchanged)\n";
        return stop.exit_code();
    }
    if (!quiet) {
        std::error_code ec;
        const auto size = fs::file_size(job.path, ec);
        const double seconds = std::chrono::duration<double>(clock::now() - start).count();
        out << "  wrote " << job.path.string() << ": " << job.frames.size()
            << (job.frames.size() == 1 ? " frame, " : " frames, ")
            << megabytes(ec ? job.total_bytes : static_cast<double>(size)) << " in "
            << format_number(std::round(seconds * 100) / 100) << " s\n";
    }
    return 0;
}

}  // namespace rodsea
