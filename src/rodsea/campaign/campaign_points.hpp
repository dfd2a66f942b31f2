#pragma once
// A campaign's state points and runs: the product of its axes, each point the base config with
// the point's coordinates and overrides applied and validated, each run a point at one seed.
// Everything is checked here, packing included, before any run starts.
#include <cstdint>
#include <string>
#include <vector>

#include "rodsea/config/campaign_file.hpp"
#include "rodsea/config/run_plan.hpp"

namespace rodsea {

struct CampaignPoint {
    // Its directory name, from its coordinates: "medium.area_fraction=0.35", or "base" for a
    // campaign without axes. Stable when values are added to an axis.
    std::string name;
    std::vector<KeySetting> coordinates;  // each axis key with its value here, in axis order
    std::vector<KeySetting> settings;     // coordinates, then the overrides that apply
    RunPlan plan;                         // at the first replicate's seed
};

struct CampaignRun {
    std::size_t point = 0;
    std::uint64_t seed = 0;
    std::string id;  // "<point name>/seed<seed>"
    // Its time.duration in this campaign (its point's, or --duration), s: a run that ended
    // shorter (a campaign extended since) is not done.
    double duration = 0.0;
};

struct CampaignGrid {
    std::vector<CampaignPoint> points;
    std::vector<CampaignRun> runs;  // point by point, replicates together
};

// The largest grid planned: 10 000 points take seconds and a few hundred MB to expand and
// check; a larger one is refused before it is expanded, with its size and its first point's cost.
inline constexpr double kMaxCampaignPoints = 10'000;
inline constexpr double kMaxCampaignRuns = 100'000;

// Throws InvalidParameter naming the point and key (or the packing that cannot be built).
CampaignGrid expand_campaign(const Campaign& campaign, const CampaignScaling& scaling,
                             const EpsilonLookup& epsilon);

// The config of one run: its point's plan at its seed.
RunPlan run_plan(const Campaign& campaign, const CampaignGrid& grid, const CampaignRun& run,
                 const CampaignScaling& scaling, const EpsilonLookup& epsilon);

// "medium.area_fraction" for species.medium.area_fraction, "rotational_diffusion" for
// noise.rotational_diffusion: the column and directory names of an axis key.
std::string short_key(const std::string& key);

// A point's or run's name in a table column `width` characters wide: whole if it fits, else its
// start and its end around "...". The end is kept because that is where names differ: the last
// axis's value and the seed (in 40: "medium.area_...m.aspect_ratio=1.25/seed1").
std::string name_in_column(const std::string& name, std::size_t width);
// The widest such column of `campaign plan` and `status`: a two-axis point and its seed whole.
inline constexpr std::size_t kNameColumnWidth = 80;

}  // namespace rodsea
