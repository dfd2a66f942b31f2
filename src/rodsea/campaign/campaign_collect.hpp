#pragma once
// `rodsea campaign collect`: every finished run analysed with the campaign's [analysis], then one
// table with a row per point (replicates combined) and one with a row per run. A partial
// campaign collects what is finished and names what is missing. A run whose analysis is already
// on disk for the same trajectory, [analysis] and rodsea version is not analysed again.
#include <filesystem>
#include <iosfwd>
#include <vector>

#include "rodsea/campaign/campaign_store.hpp"

namespace rodsea {

struct CollectResult {
    std::filesystem::path points_table, runs_table;
    std::size_t runs_analysed = 0, points_with_runs = 0;
    std::size_t runs_reused = 0;       // of runs_analysed, taken from their earlier analysis
    std::vector<std::string> missing;  // run ids not finished
    // A table that would hold fewer rows than before keeps its old self beside it
    // (<name>.previous.csv); one sentence each, saying so.
    std::vector<std::string> shrunk;
};

// Writes collected/points.csv and collected/runs.csv (atomically). Each point's scalar is the
// mean over its finished replicates; its error is the larger of the replicates' spread, sd/√n,
// and their own errors combined, √(Σσ_i²)/n: with few replicates the spread is itself uncertain
// (for n = 2 by ±70 %), and a run's own error is a floor. <name>_chi2 compares the two.
// `reanalyse`: analyse every run again, even one whose analysis is up to date.
CollectResult collect_campaign(const CampaignPaths& paths, const Campaign& campaign,
                               const CampaignGrid& grid, std::ostream& log, bool quiet,
                               bool reanalyse = false);

}  // namespace rodsea
