#include "rodsea/analyze/analyze_command.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <ostream>

#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/analyze/observable_registry.hpp"
#include "rodsea/cli/arguments.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/stored_run.hpp"

namespace rodsea {

namespace {

std::string observable_names() {
    std::string names;
    for (const ObservableInfo& o : observable_catalogue())
        names += (names.empty() ? "" : ", ") + o.name;
    return names;
}

}  // namespace

const CommandSpec& analyze_command_spec() {
    static const CommandSpec spec{
        "analyze",
        "RUN_DIR [RUN_DIR ...] [--observables NAME,...] [--from T] [--to T] "
        "[--param KEY=VALUE ...] [--out DIR] [--table FILE] [--quiet]",
        "the paper's observables with error bars",
        "Turns trajectories written by `rodsea run` into the paper's numbers (docs/analysis.md). "
        "Each run gets RUN_DIR/analysis/ (or --out DIR, one run only):\n"
        "analysis.json: every steady-state scalar with its error bar, the parameters used, the "
        "window\n"
        "<table>.csv: curves and time series (order_parameters, pair_correlation_*, flocks, ...)\n"
        "analysis.h5: g(r,θ) and G(r,θ) maps with their bin edges; flock labels per frame\n"
        "summary.csv: one row: the run's parameters and every scalar (also for several runs: "
        "--table)\n"
        "A run's first directory and its continuations (rodsea run --continue: the same run "
        "id), given together, are one run: their frames are joined in order and its analysis "
        "goes to the latest one's directory.\n"
        "Everything is checked for every run before any frame is read.",
        {{"--observables", "NAME,...",
          "comma-separated subset of: " + observable_names() +
              " (default: all that the run's species allow)"},
         {"--from", "T",
          "start of the steady window, s; default: the latest of the steady starts of the run's "
          "order series (P, S, Σ, N_m; each by Chodera's rule), which it names"},
         {"--to", "T",
          "end of the run as analysed, s: the frames after it are left out of everything, the "
          "automatic start included (default: the run's last frame)"},
         {"--param", "KEY=VALUE",
          "an analysis parameter, e.g. flocks.eps=2.25 (the keys below); may be repeated", true},
         {"--out", "DIR", "output directory for a single run (default RUN_DIR/analysis)"},
         {"--table", "FILE",
          "with several runs: the table with one row per run (default analysis-summary.csv in the "
          "current directory)"},
         {"--quiet", "", "no plan and no progress lines"}},
        "Parameters (--param KEY=VALUE; units mm and s; automatic defaults follow the box side L "
        "and the polar rod length ℓ_p):\n" +
            analysis_options_help()};
    return spec;
}

namespace {

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> parts;
    std::string part;
    for (char c : text) {
        if (c == ',') {
            if (!part.empty()) parts.push_back(part);
            part.clear();
        } else if (c != ' ') {
            part += c;
        }
    }
    if (!part.empty()) parts.push_back(part);
    return parts;
}

// Per group of replicates: each scalar from the spread of the runs, and whether the runs' own
// error bars were honest about it.
void report_replicates(const std::vector<ReplicateSummary>& groups, std::ostream& log) {
    for (const ReplicateSummary& g : groups) {
        log << "replicates: " << g.runs.size() << " runs of one state point (seeds";
        for (const std::uint64_t seed : g.seeds)
            log << " " << seed;
        log << "), mean ± spread / sqrt(n):\n";
        for (const ReplicateScalar& s : g.scalars) {
            const ReplicateEstimate& e = s.estimate;
            log << "    " << s.name << " = " << format_number(e.mean) << " ± "
                << format_number(e.error) << (s.unit.empty() ? "" : " ") << s.unit;
            if (std::isfinite(e.chi2_per_dof))
                log << "  (the runs' own errors: chi2/dof = " << format_number(e.chi2_per_dof)
                    << (e.chi2_per_dof > e.chi2_high
                            ? ", too small: use the replicates' error"
                            : (e.chi2_per_dof < e.chi2_low ? ", too large" : ", honest"))
                    << "; 95 % range " << format_number(e.chi2_low) << "–"
                    << format_number(e.chi2_high) << ")";
            log << "\n";
        }
    }
}

}  // namespace

int analyze_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& log) {
    const std::optional<Arguments> parsed = arguments_or_help(args, analyze_command_spec(), out);
    if (!parsed) return 0;
    const Arguments& words = *parsed;
    AnalyzeRequest request;
    const bool quiet = words.has("--quiet");
    if (const auto names = words.value("--observables")) {
        request.observables = split_commas(*names);
        if (request.observables.empty())
            throw InvalidParameter("--observables", "''", "a comma-separated list of names");
    }
    if (const auto from = words.value("--from"))
        request.from = parse_number("--from", *from, -std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::infinity(), "s");
    if (const auto to = words.value("--to"))
        request.to = parse_number("--to", *to, -std::numeric_limits<double>::infinity(),
                                  std::numeric_limits<double>::infinity(), "s");
    for (const std::string& kv : words.values_of("--param")) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos)
            throw InvalidParameter("--param", kv, "KEY=VALUE, e.g. flocks.eps=2.25");
        const std::string key = kv.substr(0, eq);
        set_analysis_option(request.options, key, kv.substr(eq + 1), "--param " + key);
    }
    std::optional<std::filesystem::path> out_dir, table;
    if (const auto dir = words.value("--out")) out_dir = *dir;
    if (const auto file = words.value("--table")) table = *file;
    const std::vector<std::filesystem::path> given(words.positional.begin(),
                                                   words.positional.end());
    if (given.empty())
        throw InvalidParameter("RUN_DIR", "none given",
                               "one or more run directories (see rodsea analyze --help)");
    // A run's first directory and its continuations, given together, are analysed as one run.
    const std::vector<std::vector<std::filesystem::path>> runs = group_run_parts(given);
    // The same run twice (as `a` and `./a/`) would count as two replicates with no spread.
    for (std::size_t i = 0; i < runs.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
            std::error_code ec_i, ec_j;
            const auto a = std::filesystem::weakly_canonical(runs[i].front(), ec_i);
            const auto b = std::filesystem::weakly_canonical(runs[j].front(), ec_j);
            if (!ec_i && !ec_j && a == b)
                throw InvalidParameter("RUN_DIR",
                                       runs[j].front().string() + " and " +
                                           runs[i].front().string() + ", the same run",
                                       "each run once");
        }
    if (out_dir && runs.size() > 1)
        throw InvalidParameter("--out", out_dir->string(), "only with a single RUN_DIR",
                               "each of several runs writes into its own RUN_DIR/analysis");

    std::vector<PreparedRun> prepared;
    for (const auto& run : runs) {
        prepared.push_back(prepare_run(run, request));
        check_analysis_output_directory(out_dir.value_or(prepared.back().run_dir / "analysis"));
    }
    // One run's row is in its own summary.csv; a separate table only when asked or for several.
    std::optional<std::filesystem::path> table_path = table;
    if (!table_path && runs.size() > 1) table_path = "analysis-summary.csv";
    if (table_path) {
        const std::filesystem::path parent =
            table_path->has_parent_path() ? table_path->parent_path() : ".";
        if (!std::filesystem::is_directory(parent))
            throw FileError(table_path->string(), "its directory does not exist");
    }

    std::vector<RunAnalysis> analyses;
    bool any_short = false;
    for (const PreparedRun& run : prepared) {
        const std::filesystem::path dir = out_dir.value_or(run.run_dir / "analysis");
        RunAnalysis a = analyze_run(run, log, quiet);
        write_run_analysis(a, dir);
        if (!quiet) {
            log << "  wrote " << (dir / "analysis.json").string() << " in "
                << format_number(std::round(a.seconds * 100) / 100) << " s\n";
            for (const ObservableResults& r : a.results) {
                for (const ScalarResult& s : r.scalars)
                    log << "    " << s.name << " = " << format_number(s.estimate.mean) << " ± "
                        << format_number(s.estimate.error) << (s.unit.empty() ? "" : " ") << s.unit
                        << (s.estimate.short_series() ? "  *" : "") << "\n";
                any_short = any_short || std::any_of(r.scalars.begin(), r.scalars.end(),
                                                     [](const ScalarResult& x) {
                                                         return x.estimate.short_series();
                                                     });
                for (const std::string& n : r.notes)
                    log << "    note (" << r.observable << "): " << n << "\n";
            }
        }
        analyses.push_back(std::move(a));
    }
    if (!quiet && any_short)
        log << "  * window < 50 τ_int: the error bar is an underestimate; run longer, or give "
               "several seeds for an error from replicates\n";
    if (!quiet) {
        for (const auto& [later, earlier] : same_seed_runs(analyses))
            log << "replicates: " << later.string() << " has the config and seed of "
                << earlier.string() << ": the same trajectory, counted once\n";
        report_replicates(replicate_summaries(analyses), log);
    }
    if (table_path) {
        write_file_atomically(*table_path, summary_table_csv(analyses));
        if (!quiet) log << "table: " << table_path->string() << "\n";
    }
    return 0;
}

}  // namespace rodsea
