#include "rodsea/campaign/campaign_collect.hpp"

#include <cmath>
#include <map>
#include <ostream>
#include <sstream>

#include "rodsea/analysis/statistics.hpp"
#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

AnalyzeRequest request_of(const CampaignAnalysis& a) {
    AnalyzeRequest r;
    r.observables = a.observables;
    r.from = a.from;
    for (const auto& [key, value] : a.parameters)
        set_analysis_option(r.options, key, value);
    return r;
}

std::string cell(double v) {
    return std::isfinite(v) ? exact_number(v) : "nan";
}

std::string quoted_cell(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q = "\"";
    for (const char c : text)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

struct PointScalar {
    std::string name, unit;
    std::vector<double> values, errors;
};

}  // namespace

CollectResult collect_campaign(const CampaignPaths& paths, const Campaign& campaign,
                               const CampaignGrid& grid, std::ostream& log, bool quiet) {
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
        analyses.push_back(analyze_run(prepared[k], log, true));
        write_run_analysis(analyses.back(), prepared[k].run_dir / "analysis");
        if (!quiet) log << "collect: analysed " << grid.runs[prepared_run[k]].id << "\n";
    }
    for (std::size_t k = 0; k < analyses.size(); ++k)
        by_point[grid.runs[prepared_run[k]].point].push_back(&analyses[k]);
    result.runs_analysed = analyses.size();
    result.points_with_runs = by_point.size();

    fs::create_directories(paths.collected());
    result.runs_table = paths.collected() / "runs.csv";
    write_file_atomically(result.runs_table, summary_table_csv(analyses));

    // One row per point: its coordinates, then each scalar combined over its replicates.
    std::vector<std::string> columns{"point"};
    for (const CampaignAxis& a : campaign.axes)
        for (const std::string& k : a.keys)
            columns.push_back(short_key(k));
    columns.insert(columns.end(), {"runs", "seeds"});
    std::vector<std::map<std::string, std::string>> rows;
    for (const auto& [point, runs] : by_point) {
        std::map<std::string, std::string> row;
        const CampaignPoint& p = grid.points[point];
        row["point"] = quoted_cell(p.name);
        for (const KeySetting& c : p.coordinates)
            row[short_key(c.first)] = quoted_cell(setting_text(c.second));
        row["runs"] = std::to_string(runs.size());
        std::string seeds;
        for (const RunAnalysis* a : runs)
            seeds += (seeds.empty() ? "" : " ") + std::to_string(a->run.plan.engine.seed);
        row["seeds"] = seeds;
        std::vector<PointScalar> scalars;
        for (const RunAnalysis* a : runs)
            for (const ObservableResults& r : a->results)
                for (const ScalarResult& s : r.scalars) {
                    auto it = std::find_if(scalars.begin(), scalars.end(),
                                           [&](const PointScalar& x) { return x.name == s.name; });
                    if (it == scalars.end())
                        it = scalars.insert(scalars.end(), {s.name, s.unit, {}, {}});
                    it->values.push_back(s.estimate.mean);
                    it->errors.push_back(s.estimate.error);
                }
        for (const PointScalar& s : scalars) {
            const ReplicateEstimate e = combine_replicates(s.values, s.errors);
            double own = 0.0;
            std::size_t n = 0;
            for (std::size_t i = 0; i < s.values.size(); ++i)
                if (std::isfinite(s.values[i])) {
                    own += std::isfinite(s.errors[i]) ? s.errors[i] * s.errors[i] : NAN;
                    ++n;
                }
            own = n ? std::sqrt(own) / static_cast<double>(n) : NAN;
            const double error = e.replicates >= 2 && std::isfinite(e.error)
                                     ? (std::isfinite(own) ? std::max(e.error, own) : e.error)
                                     : own;
            for (const std::string& c : {s.name, s.name + "_err", s.name + "_chi2"})
                if (std::find(columns.begin(), columns.end(), c) == columns.end())
                    columns.push_back(c);
            row[s.name] = cell(e.mean);
            row[s.name + "_err"] = cell(error);
            row[s.name + "_chi2"] = cell(e.chi2_per_dof);
        }
        rows.push_back(std::move(row));
    }
    std::ostringstream csv;
    csv << "# rodsea " << RODSEA_VERSION << " campaign " << campaign.name
        << ": one row per point with finished runs; its axis values, the runs and seeds, then "
           "each scalar's mean over the replicates, its error (the larger of the replicates' "
           "spread sd/sqrt(n) and their own errors sqrt(sum sigma^2)/n) and chi2/dof of the "
           "spread against the runs' own errors (nan with one run); units as in runs.csv and "
           "docs/analysis.md\n";
    for (std::size_t c = 0; c < columns.size(); ++c)
        csv << (c ? "," : "") << columns[c];
    csv << "\n";
    for (const auto& row : rows) {
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const auto it = row.find(columns[c]);
            csv << (c ? "," : "") << (it == row.end() ? "" : it->second);
        }
        csv << "\n";
    }
    result.points_table = paths.collected() / "points.csv";
    write_file_atomically(result.points_table, csv.str());
    return result;
}

}  // namespace rodsea
