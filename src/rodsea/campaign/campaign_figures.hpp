#pragma once
// The [[figure]]s of a campaign, drawn by `collect` into collected/figures/ with rodsea's own
// picture commands: curves and maps by `rodsea plot` from collected/figures.json (which says
// which columns and points of points.csv each shows), `analysis` figures by `rodsea plot` of
// each chosen point's first finished replicate, snapshots by `rodsea render` of its last frame,
// movies by `rodsea movie RUN1 RUN2 ...` of the chosen points side by side.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/campaign/campaign_store.hpp"

namespace rodsea {

struct FiguresDrawn {
    std::vector<std::filesystem::path> files;  // every PNG and MP4 written
    std::vector<std::string> problems;         // "figure <name>: why a command refused it"
    std::vector<std::string> unfinished;       // "figure <name>: k of its points ..."
};

// The points a figure shows: those whose coordinates match its `when` (all without one).
std::vector<std::size_t> figure_points(const CampaignFigure& figure, const CampaignGrid& grid);

// Draws every figure from what is finished; a figure whose points have no finished run yet is
// named in `unfinished`, one a picture command refused in `problems`.
FiguresDrawn draw_campaign_figures(const CampaignPaths& paths, const Campaign& campaign,
                                   const CampaignGrid& grid, std::ostream& log);

}  // namespace rodsea
