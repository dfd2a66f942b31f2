#include "rodsea/view/plot_command.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <ostream>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/cli/child_process.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/run_files.hpp"
#include "rodsea/text_file.hpp"
#include "rodsea/view/python_script.hpp"

namespace rodsea {

const CommandSpec& plot_command_spec() {
    static const CommandSpec spec{
        "plot",
        "INPUT -o DIR [--dpi D] [--only F,..] [--quiet]",
        "the paper's figure types, drawn with matplotlib",
        "Draws the paper's figure types as PNG files in DIR (created if needed) with matplotlib, "
        "from\n"
        "  one run's analysis  RUN_DIR, RUN_DIR/analysis or its analysis.json (`rodsea analyze "
        "RUN_DIR`): order_parameters, autocorrelation (C(t), C2(t) and their D_r fits), "
        "flocks_time, flock_sizes, g_r_theta and G_r_theta (polar heat maps in the corotating "
        "frame with the 70 % contour), pair_correlation, segregation, bands (transverse and "
        "longitudinal), medium_velocity\n"
        "  a table of runs     T.csv from `rodsea analyze RUN1 RUN2 ... --table T.csv` (or a "
        "run's summary.csv): P and Sigma vs phi_a and vs D_r with error bars, the phase diagram "
        "(ordered P > 0.5 vs disordered in the (phi_a, D_r) plane), and S, sigma_f, N_m, N_avg, "
        "D_r vs phi_a\n"
        "What the input cannot give (a run without polar rods has no g(r,theta)) is skipped with "
        "a note. Every input is checked before the first figure is drawn; each PNG is written "
        "under a temporary name and renamed, so none is ever half-written. Prints the PNG files, "
        "one per line. Figures and what they mirror in the paper: docs/plots.md.",
        {{"-o,--output", "DIR", "where the PNG files go"},
         {"--dpi", "D",
          "pixels per inch, 20 to 600 (default 150: a 6.5 x 4.5 in figure is 975 x 675)"},
         {"--only", "F,..",
          "only these figures, by file name (.png optional): --only g_r_theta,G_r_theta"},
         {"--quiet", "", "no notes on what was skipped"}},
        "Runs /usr/bin/python3 (env RODSEA_PYTHON overrides) on rodsea_plot.py in an installed "
        "rodsea's share/rodsea/scripts, or else the source tree's scripts/ (env "
        "RODSEA_SCRIPTS_DIR overrides the folder); needs Debian's "
        "python3-matplotlib, python3-numpy and python3-h5py: ./scripts/install-deps.sh installs "
        "them.\nExit codes: 0 done; 1 Python or one of its modules missing; 2 bad input (nothing "
        "written); 74 a file could not be read or written."};
    return spec;
}

namespace {

namespace fs = std::filesystem;

// The value after `field` in an analysis cache key ("rodsea V|run ID|frames N|first step A|last
// step B|..."), or "".
std::string cache_key_field(const std::string& key, const std::string& field) {
    const std::size_t at = key.find("|" + field + " ");
    if (at == std::string::npos) return "";
    const std::size_t from = at + field.size() + 2;
    return key.substr(from, key.find('|', from) - from);
}

// Figures drawn from an analysis/ that no longer describes its run (the run was extended, or
// run again, since): a note saying so, or none. Quiet about anything it cannot read: the script
// reports unreadable inputs itself.
std::optional<std::string> stale_analysis_note(const fs::path& input) {
    std::error_code ec;
    fs::path analysis = input;
    if (input.filename() == "analysis.json") analysis = input.parent_path();
    if (fs::exists(analysis / kTrajectoryFile, ec)) analysis /= "analysis";
    const fs::path run = analysis.parent_path();
    const fs::path json = analysis / "analysis.json";
    if (!fs::exists(json, ec) || !fs::exists(run / kTrajectoryFile, ec)) return std::nullopt;
    try {
        const std::string text = read_text_file(json);
        const std::size_t at = text.find("\"cache_key\": \"");
        if (at == std::string::npos) return std::nullopt;
        const std::size_t from = at + 14;
        const std::string key = text.substr(from, text.find('"', from) - from);
        const TrajectoryReader reader(run / kTrajectoryFile);
        if (reader.steps().empty()) return std::nullopt;
        const std::string last = std::to_string(reader.steps().back());
        const std::string id = read_run_id(run / kTrajectoryFile);
        // An analysis cut short by --to ends before the run by design ("|to|" in its key).
        const bool cut_short = key.find("|to|") != std::string::npos;
        if (cache_key_field(key, "run") == id &&
            (cut_short || cache_key_field(key, "last step") == last))
            return std::nullopt;
        return analysis.string() + " was made from " +
               (cache_key_field(key, "run") == id
                    ? "this run up to step " + cache_key_field(key, "last step") +
                          "; it now reaches step " + last
                    : "another run (run id " + cache_key_field(key, "run") + ")") +
               ": rodsea analyze " + run.string() + " again for figures of the run as it is";
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

}  // namespace

int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const std::optional<Arguments> parsed = arguments_or_help(args, plot_command_spec(), out);
    if (!parsed) return kExitOk;
    const Arguments& a = *parsed;
    if (a.positional.size() != 1)
        throw InvalidParameter("INPUT", std::to_string(a.positional.size()) + " given",
                               "exactly one: a run's analysis directory, its analysis.json or a "
                               "table CSV (see rodsea plot --help)");
    const std::string input = a.positional[0];
    const auto output = a.value("--output");
    if (!output || output->empty())
        throw InvalidParameter("-o", output ? "''" : "missing",
                               "the directory for the PNG files: rodsea plot INPUT -o DIR");
    const long long dpi = parse_count("--dpi", a.value("--dpi").value_or("150"), 20, 600);
    std::error_code ec;
    if (!fs::exists(input, ec)) throw FileError(input, "no such file or directory");

    const PythonScriptLookup lookup = locate_python_script(
        "rodsea_plot.py", "python3, python3-matplotlib, python3-numpy, python3-h5py");
    if (!lookup.found) {
        err << "rodsea plot: " << lookup.problem << "\n";
        return kExitFailure;
    }
    if (const auto note = stale_analysis_note(input)) err << "rodsea plot: note: " << *note << "\n";
    const std::string& python = lookup.found->python;
    const std::string& script = lookup.found->script;
    std::string output_flag = "--output=";
    output_flag += *output;
    std::vector<std::string> argv{python, "-B", script, output_flag, "--dpi", std::to_string(dpi)};
    if (const auto only = a.value("--only")) {
        std::string only_flag = "--only=";
        only_flag += *only;
        argv.push_back(only_flag);
    }
    if (a.has("--quiet")) argv.emplace_back("--quiet");
    argv.emplace_back("--");  // INPUT is never taken for an option, whatever its name
    argv.push_back(input);
    const std::string command = python + " " + script;
    const int code = run_program(std::move(argv), out, err, kExitFailure);
    // The script's own messages, if any, came first; the failure is always said.
    if (code != kExitOk && code != kExitBadInput)
        err << "rodsea plot: " << command << " failed ("
            << (code > 128 ? "killed by signal " + std::to_string(code - 128)
                           : "exit code " + std::to_string(code))
            << "); nothing more was drawn\n";
    return code;
}

}  // namespace rodsea
