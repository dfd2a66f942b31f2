#include "rodsea/analyze/analyze_command.hpp"

#include <charconv>
#include <cmath>
#include <ostream>

#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/analyze/observable_registry.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"

namespace rodsea {

const char* const kAnalyzeHelp =
    R"(rodsea analyze RUN_DIR [RUN_DIR ...] [--observables NAME,...] [--from T]
               [--param KEY=VALUE ...] [--out DIR] [--table FILE] [--quiet]

Turns trajectories written by `rodsea run` into the paper's numbers (docs/analysis.md). Each run
gets RUN_DIR/analysis/ (or --out DIR, one run only):
  analysis.json   every steady-state scalar with its error bar, the parameters used, the window
  <table>.csv     curves and time series (order_parameters, pair_correlation_*, flocks, ...)
  analysis.h5     g(r,θ) and G(r,θ) maps with their bin edges; flock labels per frame
  summary.csv     one row: the run's parameters and every scalar (also for several runs: --table)
Everything is checked for every run before any frame is read.

  --observables   comma-separated subset of: order, pair, corotating, autocorrelation, flocks,
                  segregation, medium_velocity (default: all that the run's species allow)
  --from T        start of the steady window, s; default: the earliest start that maximises the
                  number of independent samples of the run's P (Chodera's rule)
  --param K=V     an analysis parameter (units in docs/analysis.md), e.g. flocks.eps=2.25
  --out DIR       output directory for a single run (default RUN_DIR/analysis)
  --table FILE    with several runs: the table with one row per run (default
                  analysis-summary.csv in the current directory)
  --quiet         no plan and no progress lines
)";

namespace {

double parse_seconds(const std::string& flag, const std::string& text) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v))
        throw InvalidParameter(flag, "'" + text + "'", "a time in seconds, e.g. 0.5");
    return v;
}

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

}  // namespace

int analyze_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& log) {
    AnalyzeRequest request;
    std::vector<std::filesystem::path> runs;
    std::optional<std::filesystem::path> out_dir, table;
    bool quiet = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto next = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw InvalidParameter(a, "nothing", "a value after it");
            return args[++i];
        };
        if (a == "--help") {
            out << kAnalyzeHelp;
            return 0;
        } else if (a == "--quiet") {
            quiet = true;
        } else if (a == "--observables") {
            request.observables = split_commas(next());
            if (request.observables.empty())
                throw InvalidParameter("--observables", "''", "a comma-separated list of names");
        } else if (a == "--from") {
            request.from = parse_seconds(a, next());
        } else if (a == "--param") {
            const std::string& kv = next();
            const auto eq = kv.find('=');
            if (eq == std::string::npos)
                throw InvalidParameter("--param", kv, "KEY=VALUE, e.g. flocks.eps=2.25");
            set_analysis_option(request.options, kv.substr(0, eq), kv.substr(eq + 1));
        } else if (a == "--out") {
            out_dir = next();
        } else if (a == "--table") {
            table = next();
        } else if (a.rfind("--", 0) == 0) {
            throw InvalidParameter(a, "an unknown option of 'analyze'",
                                   "--observables --from --param --out --table --quiet --help");
        } else {
            runs.emplace_back(a);
        }
    }
    if (runs.empty())
        throw InvalidParameter("RUN_DIR", "none given",
                               "one or more run directories (see rodsea analyze --help)");
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
                        << (s.estimate.short_series()
                                ? "  (window < 50 τ_int: the error bar is an underestimate)"
                                : "")
                        << "\n";
                for (const std::string& n : r.notes)
                    log << "    note (" << r.observable << "): " << n << "\n";
            }
        }
        analyses.push_back(std::move(a));
    }
    if (table_path) {
        write_file_atomically(*table_path, summary_table_csv(analyses));
        if (!quiet) log << "table: " << table_path->string() << "\n";
    }
    return 0;
}

}  // namespace rodsea
