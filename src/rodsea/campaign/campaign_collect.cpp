#include "rodsea/campaign/campaign_collect.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>

#include "rodsea/analysis/statistics.hpp"
#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/csv_table.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

AnalyzeRequest request_of(const CampaignAnalysis& a) {
    AnalyzeRequest r;
    r.observables = a.observables;
    r.from = a.from;
    r.to = a.to;
    for (const auto& [key, value] : a.parameters)
        set_analysis_option(r.options, key, value, campaign_analysis_parameter_name(key));
    return r;
}

std::string cell(double v) {
    return std::isfinite(v) ? exact_number(v) : "nan";
}

std::size_t data_rows(const std::string& csv) {
    std::size_t lines = 0;
    std::istringstream in(csv);
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') ++lines;
    return lines == 0 ? 0 : lines - 1;  // less the header
}

// Writes `table` with `text`; one that held more rows than `text` has (runs removed, values
// taken off an axis) is kept first as <name>.previous.csv, and the sentence saying so is added
// to `shrunk`: collect never loses rows without a word.
void write_table(const fs::path& table, const std::string& text, std::vector<std::string>& shrunk) {
    std::ifstream in(table, std::ios::binary);
    if (in) {
        std::ostringstream old;
        old << in.rdbuf();
        const std::size_t before = data_rows(old.str()), now = data_rows(text);
        if (now < before) {
            const fs::path kept = fs::path(table).replace_extension(".previous.csv");
            write_file_atomically(kept, old.str());
            shrunk.push_back(table.filename().string() + " held " + std::to_string(before) +
                             " rows, now " + std::to_string(now) + ": the old table is kept as " +
                             kept.string());
        }
    }
    write_file_atomically(table, text);
}

}  // namespace

CollectResult collect_campaign(const CampaignPaths& paths, const Campaign& campaign,
                               const CampaignGrid& grid, std::ostream& log, bool quiet,
                               bool reanalyse) {
    CollectResult result;
    const AnalyzeRequest request = request_of(campaign.analysis);
    // Every finished run is prepared (and so checked) before any is analysed.
    std::vector<PreparedRun> prepared;
    std::vector<std::size_t> prepared_run;
    for (std::size_t i = 0; i < grid.runs.size(); ++i) {
        if (run_status(paths, grid.runs[i]).state != RunState::done) {
            result.missing.push_back(grid.runs[i].id);
            continue;
        }
        prepared.push_back(prepare_run(paths.run_dir(grid.runs[i]), request));
        prepared_run.push_back(i);
        check_analysis_output_directory(prepared.back().run_dir / "analysis");
    }
    std::vector<RunAnalysis> analyses;
    std::map<std::size_t, std::vector<const RunAnalysis*>> by_point;
    analyses.reserve(prepared.size());
    for (std::size_t k = 0; k < prepared.size(); ++k) {
        const fs::path out_dir = prepared[k].run_dir / "analysis";
        const std::string& id = grid.runs[prepared_run[k]].id;
        if (!reanalyse)
            if (std::optional<RunAnalysis> earlier = reuse_run_analysis(prepared[k], out_dir)) {
                analyses.push_back(std::move(*earlier));
                ++result.runs_reused;
                if (!quiet) log << "collect: " << id << " unchanged since its analysis\n";
                continue;
            }
        analyses.push_back(analyze_run(prepared[k], log, true));
        write_run_analysis(analyses.back(), out_dir);
        if (!quiet) log << "collect: analysed " << id << "\n";
    }
    for (std::size_t k = 0; k < analyses.size(); ++k)
        by_point[grid.runs[prepared_run[k]].point].push_back(&analyses[k]);
    result.runs_analysed = analyses.size();
    result.points_with_runs = by_point.size();

    fs::create_directories(paths.collected());
    result.runs_table = paths.collected() / "runs.csv";
    write_table(result.runs_table, summary_table_csv(analyses), result.shrunk);

    // One row per point: its coordinates, then each scalar combined over its replicates.
    std::vector<std::string> first{"point"};
    for (const CampaignAxis& a : campaign.axes)
        for (const std::string& k : a.keys)
            first.push_back(short_key(k));
    first.insert(first.end(), {"runs", "seeds"});
    CsvTable table(first);
    for (const auto& [point, runs] : by_point) {
        CsvTable::Row row;
        const CampaignPoint& p = grid.points[point];
        table.set(row, "point", csv_quoted(p.name));
        for (const KeySetting& c : p.coordinates)
            table.set(row, short_key(c.first), csv_quoted(setting_text(c.second)));
        const ReplicateSummary summary = summarise_replicates(runs);
        table.set(row, "runs", std::to_string(runs.size()));
        std::string seeds;
        for (const std::uint64_t seed : summary.seeds) {
            if (!seeds.empty()) seeds += ' ';  // (not ("" : " ") + ...: GCC 12 -Wrestrict)
            seeds += std::to_string(seed);
        }
        table.set(row, "seeds", seeds);
        for (const ReplicateScalar& s : summary.scalars) {
            const ReplicateEstimate& e = s.estimate;
            const double error =
                e.replicates >= 2 && std::isfinite(e.error)
                    ? (std::isfinite(e.own_error) ? std::max(e.error, e.own_error) : e.error)
                    : e.own_error;
            table.set(row, s.name, cell(e.mean));
            table.set(row, s.name + "_err", cell(error));
            table.set(row, s.name + "_chi2", cell(e.chi2_per_dof));
        }
        table.add(std::move(row));
    }
    const std::string comment =
        std::string("rodsea ") + RODSEA_VERSION + " campaign " + campaign.name +
        ": one row per point with finished runs; its axis values, the runs and seeds, then each "
        "scalar's mean over the replicates, its error (the larger of the replicates' spread "
        "sd/sqrt(n) and their own errors sqrt(sum sigma^2)/n) and chi2/dof of the spread against "
        "the runs' own errors (nan with one run); units as in runs.csv and docs/analysis.md";
    result.points_table = paths.collected() / "points.csv";
    write_table(result.points_table, table.text(comment), result.shrunk);
    return result;
}

}  // namespace rodsea
