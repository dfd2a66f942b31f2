#pragma once
// A campaign file: one TOML file for a figure's grid of state points. A base config (a file or an
// inline [base] table), axes over config keys (their product; a zipped axis moves several keys
// together), per-point overrides, replicates, the analysis to run on every point and the figures
// to draw. Read and checked whole here, before any point is built or run; docs/campaigns.md is
// generated from the key table below (campaign_reference_markdown).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rodsea/config/config_file.hpp"
#include "rodsea/config/config_values.hpp"
#include "rodsea/config/run_plan.hpp"

namespace rodsea {

// A config key as an axis names it: "box.side", "noise.rotational_diffusion", or
// "species.<name>.<key>" for a key of the [[species]] element with that name.
using KeySetting = std::pair<std::string, config::Value>;

struct CampaignAxis {
    std::vector<std::string> keys;                   // one key, or several zipped
    std::vector<std::vector<config::Value>> values;  // values[i][k]: key k at the axis' i-th step
};

// At every point whose coordinates match all of `when`, the keys of `set` take these values.
struct CampaignOverride {
    std::vector<KeySetting> when, set;
};

struct CampaignAnalysis {
    std::optional<double> from;                                   // s; none: automatic window
    std::optional<double> to;                                     // s; none: the run's end
    std::vector<std::string> observables;                         // empty: all that apply
    std::vector<std::pair<std::string, std::string>> parameters;  // --param KEY=VALUE
};

// How the campaign file names an [analysis] parameter, for its errors: "analysis.parameters.KEY".
inline std::string campaign_analysis_parameter_name(const std::string& key) {
    return "analysis.parameters." + key;
}

// What a [[figure]] draws: curves of collected scalars against an axis, a map of one scalar over
// two axes (a phase diagram), one of `rodsea plot`'s figures of a run's analysis per point, the
// final snapshot per point, or the points' runs side by side in one movie.
enum class FigureKind { curve, map, analysis, snapshot, movie };
const char* to_string(FigureKind kind);

struct CampaignFigure {
    std::string name;  // the file's name, without extension
    FigureKind kind = FigureKind::curve;
    std::string x;                // curve, map: an axis key
    std::vector<std::string> y;   // curve: scalar names (P_polar, Sigma, ...); map: one
    std::string series;           // curve: one curve per value ("" for one); map: vertical axis
    std::optional<double> level;  // map: the contour drawn (P = 0.5 for the order boundary)
    std::string plot;             // analysis: the `rodsea plot` figure (g_r_theta, ...)
    // Which points (analysis, snapshot, movie, and every kind's curves): an axis key and the
    // values it may take; empty: every point.
    std::vector<std::pair<std::string, std::vector<config::Value>>> when;
    std::string xlabel, ylabel, title;
    std::string series_label;  // the legend's name for the series axis ("φ_p"); "": the key
    bool logx = false, logy = false;
};

struct Campaign {
    std::filesystem::path file;  // where it was read from ("" for a string)
    std::string name, description;
    std::string base_source;  // the base config's file, or "<campaign file> [base]"
    std::string base_toml;    // the base config's text
    int replicates = 1;
    std::uint64_t first_seed = 1;
    std::vector<CampaignAxis> axes;
    std::vector<CampaignOverride> overrides;
    CampaignAnalysis analysis;
    std::vector<CampaignFigure> figures;
};

// Throws ConfigSyntaxError for bad TOML, InvalidParameter naming the key path (campaign.replicates,
// axis[1].values, override[0].set) for anything else, FileError for an unreadable file.
Campaign load_campaign_file(const std::filesystem::path& path);
Campaign load_campaign_string(std::string_view toml, std::string_view source_name,
                              const std::filesystem::path& directory = {});

// How a campaign is run at a given size: --scale F multiplies the box side by F (area fractions
// kept, counts given as counts scaled by F²); --duration replaces every point's time.duration.
struct CampaignScaling {
    double scale = 1.0;
    std::optional<double> duration;  // s
};

// The base config with `settings` applied, validated as a config (the keys of a setting that
// excludes another drop the other: an axis over area_fraction replaces a count). Throws
// InvalidParameter naming `what` and the key (with did-you-mean) or the config's own error.
RunPlan config_with_settings(const std::string& base_toml, const std::string& base_source,
                             const std::vector<KeySetting>& settings, const std::string& what,
                             const CampaignScaling& scaling = {},
                             const EpsilonLookup& epsilon = {});

// Checks that `key` names a config key an axis may set, and that `value` suits it; throws
// InvalidParameter named `where` (axis[0].values[1]), saying it is `at` (file and line).
void check_key_setting(const std::string& key, const config::Value& value, const std::string& where,
                       const std::string& at = "");

// A setting's value as it appears in names and tables: "0.35", "isotropic".
std::string setting_text(const config::Value& value);

// docs/campaigns.md's key reference.
std::string campaign_reference_markdown();

}  // namespace rodsea
