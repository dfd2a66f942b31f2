// rodsea: command-line entry. Each command parses its options, checks its whole input, says
// what it will do, then does it. Exit codes: see ExitCode in rodsea/run/run_driver.hpp.
#include <unistd.h>

#include <csignal>

#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rodsea/analyze/analyze_command.hpp"
#include "rodsea/calibration/calibrate_command.hpp"
#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/error.hpp"
#include "rodsea/meanfield/mean_field.hpp"
#include "rodsea/run/plan_report.hpp"
#include "rodsea/run/run_driver.hpp"
#include "rodsea/view/export_command.hpp"
#include "rodsea/view/movie_command.hpp"
#include "rodsea/view/plot_command.hpp"
#include "rodsea/view/render_command.hpp"

namespace {

using rodsea::ExitCode;

constexpr const char* kUsage =
    R"(rodsea — vibrated granular rods: polar rods in a sea of apolar rods or beads

usage:
  rodsea run CONFIG [--out DIR] [--overwrite] [--quiet]   start a simulation
  rodsea run --resume DIR [--quiet]                       continue one from its checkpoint
  rodsea info CONFIG                                      what CONFIG would simulate
  rodsea config --defaults | --reference                  a complete default config, or the
                                                          key reference (docs/config.md)
  rodsea analyze RUN_DIR... [--from T] [--observables ..] the paper's observables with error
                                                          bars (docs/analysis.md)
  rodsea meanfield [--a A --alpha AL ...]                 the paper's mean-field model
                                                          (docs/meanfield.md)
  rodsea calibrate CONFIG [--out DIR] [--threads N]     single-body speed and D_r over ε, gap,
                                                          dt (docs/validation.md)
  rodsea render RUN_DIR [--frame N|--time T] [-o F.png] a top view of one frame
  rodsea movie RUN_DIR [-o F.mp4] [--fps F --every K]   an H.264 movie of the run (ffmpeg)
                                                          (both: docs/visualisation.md)
  rodsea plot ANALYSIS_DIR|TABLE.csv -o DIR [--dpi D]   the paper's figure types, matplotlib
                                                          (docs/plots.md)
  rodsea export RUN_DIR --format lammps-dump|xyz -o F   one particle per sphere, for VMD and
                                                          OVITO (docs/export.md)
  rodsea help COMMAND | --help | --version

Units everywhere: mm, s (and rad, Hz); masses in an arbitrary unit. Examples: examples/*.toml.
Exit codes: 0 done; 1 unexpected failure; 2 bad input (nothing done); 74 a file could not be
read or written (a run in progress keeps its last checkpoint; the message says what to do);
130/143 stopped by SIGINT/SIGTERM (a checkpoint was written).
)";

constexpr const char* kRunHelp = R"(rodsea run CONFIG [--out DIR] [--overwrite] [--quiet]
rodsea run --resume DIR [--quiet]

Reads CONFIG (TOML; every key in docs/config.md), checks all of it and the packing, prints the
plan, builds the initial state (every body flat on the base, no overlaps) and runs it, writing
into DIR (default: out/<config name>):
  config.toml      the full resolved config        trajectory.h5   H5MD trajectory + time series
  timeseries.csv   the time series as CSV          checkpoint.h5   the latest checkpoint
On a terminal a progress bar shows simulated time, ETA, steps/s and P; otherwise a log line
every 5 %. Checkpoints are written every output.checkpoint_interval minutes of wall time and on
SIGINT/SIGTERM (Ctrl-C stops cleanly); --resume continues bit for bit where it stopped.

  --out DIR      output directory; refused if it exists and is not empty
  --overwrite    replace the run files in an existing DIR
  --resume DIR   continue the run in DIR from its checkpoint.h5
  --quiet        no plan and no progress (errors are still printed)
)";

constexpr const char* kInfoHelp = R"(rodsea info CONFIG

Prints what CONFIG would simulate, without running it: the box and drive (amplitude A, peak
plate speed), counts per species with spheres, projected areas and actual area fractions, the
number of steps, the expected memory and output size, whether the packing is possible, and every
MODEL.md CHOICE in force.
)";

constexpr const char* kConfigHelp = R"(rodsea config --defaults | --reference

  --defaults    print a complete config with every key at its default (commented with unit and
                allowed range): a starting point for your own
  --reference   print the key reference in Markdown (this is docs/config.md)
)";

struct Arguments {
    std::vector<std::string> positional;
    std::map<std::string, std::string> values;  // --flag VALUE
    std::vector<std::string> switches;          // --flag

    bool has(std::string_view flag) const {
        for (const std::string& s : switches)
            if (s == flag) return true;
        return false;
    }
    std::optional<std::string> value(const std::string& flag) const {
        auto it = values.find(flag);
        if (it == values.end()) return std::nullopt;
        return it->second;
    }
};

// Splits argv by the flags a command accepts; anything else is an error naming it.
Arguments parse(int argc, char** argv, int first, const std::vector<std::string>& valued,
                const std::vector<std::string>& switches, std::string_view command) {
    Arguments a;
    for (int i = first; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.rfind("--", 0) != 0) {
            a.positional.push_back(arg);
            continue;
        }
        if (std::find(valued.begin(), valued.end(), arg) != valued.end()) {
            if (i + 1 >= argc) throw rodsea::InvalidParameter(arg, "nothing", "a value after it");
            a.values[arg] = argv[++i];
        } else if (std::find(switches.begin(), switches.end(), arg) != switches.end()) {
            a.switches.push_back(arg);
        } else {
            std::string allowed;
            for (const auto& f : valued)
                allowed += (allowed.empty() ? "" : " ") + f;
            for (const auto& f : switches)
                allowed += (allowed.empty() ? "" : " ") + f;
            throw rodsea::InvalidParameter(
                arg, "an unknown option of '" + std::string(command) + "'", allowed);
        }
    }
    return a;
}

bool stdout_is_terminal() {
    return ::isatty(STDOUT_FILENO) == 1;
}

int command_run(int argc, char** argv) {
    const Arguments a =
        parse(argc, argv, 2, {"--out", "--resume"}, {"--overwrite", "--quiet", "--help"}, "run");
    if (a.has("--help")) {
        std::cout << kRunHelp;
        return ExitCode::kExitOk;
    }
    rodsea::RunOptions options;
    options.quiet = a.has("--quiet");
    options.overwrite = a.has("--overwrite");
    if (const auto dir = a.value("--resume")) {
        if (!a.positional.empty() || a.value("--out") || options.overwrite)
            throw rodsea::InvalidParameter("--resume", *dir, "alone (with --quiet at most)",
                                           "the config and output directory come from DIR");
        options.out_dir = *dir;
        return rodsea::resume_run(*dir, options, std::cout, std::cerr, stdout_is_terminal());
    }
    if (a.positional.size() != 1)
        throw rodsea::InvalidParameter("CONFIG", std::to_string(a.positional.size()) + " given",
                                       "exactly one config file (see rodsea run --help)");
    const std::filesystem::path config = a.positional[0];
    const rodsea::RunPlan plan =
        rodsea::load_config_file(config, rodsea::calibration_table_lookup());
    options.out_dir =
        a.value("--out").value_or((std::filesystem::path("out") / config.stem()).string());
    return rodsea::start_run(plan, options, std::cout, std::cerr, stdout_is_terminal());
}

int command_info(int argc, char** argv) {
    const Arguments a = parse(argc, argv, 2, {}, {"--help"}, "info");
    if (a.has("--help")) {
        std::cout << kInfoHelp;
        return ExitCode::kExitOk;
    }
    if (a.positional.size() != 1)
        throw rodsea::InvalidParameter("CONFIG", std::to_string(a.positional.size()) + " given",
                                       "exactly one config file (see rodsea info --help)");
    const rodsea::RunPlan plan =
        rodsea::load_config_file(a.positional[0], rodsea::calibration_table_lookup());
    std::cout << "rodsea info " << a.positional[0] << "\n";
    rodsea::describe_plan(plan, std::cout);
    return ExitCode::kExitOk;
}

int command_config(int argc, char** argv) {
    const Arguments a = parse(argc, argv, 2, {}, {"--defaults", "--reference", "--help"}, "config");
    if (a.has("--help") || (a.has("--defaults") == a.has("--reference"))) {
        std::cout << kConfigHelp;
        return a.has("--help") ? ExitCode::kExitOk : ExitCode::kExitBadInput;
    }
    std::cout << (a.has("--defaults") ? rodsea::default_config_toml()
                                      : rodsea::config_reference_markdown());
    return ExitCode::kExitOk;
}

std::vector<std::string> words_after_command(int argc, char** argv) {
    return std::vector<std::string>(argv + 2, argv + argc);
}

int command_analyze(int argc, char** argv) {
    return rodsea::analyze_command(words_after_command(argc, argv), std::cout, std::cout);
}

int command_meanfield(int argc, char** argv) {
    return rodsea::meanfield_command(words_after_command(argc, argv), std::cout);
}

int command_calibrate(int argc, char** argv) {
    return rodsea::calibrate_command(words_after_command(argc, argv), std::cout, std::cerr);
}

int command_render(int argc, char** argv) {
    return rodsea::render_command(words_after_command(argc, argv), std::cout, std::cerr);
}

int command_movie(int argc, char** argv) {
    return rodsea::movie_command(words_after_command(argc, argv), std::cout, std::cerr);
}

int command_plot(int argc, char** argv) {
    return rodsea::plot_command(words_after_command(argc, argv), std::cout, std::cerr);
}

int command_export(int argc, char** argv) {
    return rodsea::export_command(words_after_command(argc, argv), std::cout, std::cerr);
}

}  // namespace

int main(int argc, char** argv) {
    // Output piped into `head` or a closed terminal must not kill a command halfway through a
    // file it is writing: a failed write to stdout is harmless, a half-written output is not.
    std::signal(SIGPIPE, SIG_IGN);
    if (argc < 2 || std::string_view(argv[1]) == "--help" || std::string_view(argv[1]) == "-h") {
        std::cout << kUsage;
        return argc < 2 ? ExitCode::kExitBadInput : ExitCode::kExitOk;
    }
    const std::string_view command = argv[1];
    if (command == "--version") {
        std::cout << "rodsea " << RODSEA_VERSION << "\n";
        return ExitCode::kExitOk;
    }
    const std::map<std::string_view, std::function<int(int, char**)>> commands{
        {"run", command_run},
        {"info", command_info},
        {"config", command_config},
        {"analyze", command_analyze},
        {"meanfield", command_meanfield},
        {"calibrate", command_calibrate},
        {"render", command_render},
        {"movie", command_movie},
        {"plot", command_plot},
        {"export", command_export}};
    if (command == "help") {
        const std::string_view topic = argc > 2 ? argv[2] : "";
        std::cout << (topic == "run"         ? kRunHelp
                      : topic == "info"      ? kInfoHelp
                      : topic == "config"    ? kConfigHelp
                      : topic == "analyze"   ? rodsea::kAnalyzeHelp
                      : topic == "meanfield" ? rodsea::kMeanfieldHelp
                      : topic == "calibrate" ? rodsea::kCalibrateHelp
                      : topic == "render"    ? rodsea::kRenderHelp
                      : topic == "movie"     ? rodsea::kMovieHelp
                      : topic == "plot"      ? rodsea::kPlotHelp
                      : topic == "export"    ? rodsea::kExportHelp
                                             : kUsage);
        return ExitCode::kExitOk;
    }
    const auto it = commands.find(command);
    if (it == commands.end()) {
        std::cerr << "rodsea: unknown command '" << command
                  << "' (commands: run, info, config, analyze, meanfield, calibrate, render, "
                     "movie, plot, "
                     "export, help; see rodsea --help)\n";
        return ExitCode::kExitBadInput;
    }
    try {
        return it->second(argc, argv);
    } catch (const std::invalid_argument& e) {  // InvalidParameter, ConfigSyntaxError
        std::cerr << "rodsea: " << e.what() << "\n";
        return ExitCode::kExitBadInput;
    } catch (const rodsea::FileError& e) {
        std::cerr << "rodsea: " << e.what() << "\n";
        return ExitCode::kExitIoError;
    } catch (const std::exception& e) {
        std::cerr << "rodsea: " << e.what() << "\n";
        return ExitCode::kExitFailure;
    }
}
