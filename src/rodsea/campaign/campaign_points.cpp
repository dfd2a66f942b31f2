#include "rodsea/campaign/campaign_points.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string_view>

#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable_registry.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"
#include "rodsea/run/plan_report.hpp"
#include "rodsea/run/steady_stop.hpp"

namespace rodsea {

std::string short_key(const std::string& key) {
    if (key.rfind("species.", 0) == 0) return key.substr(8);
    const std::size_t dot = key.find('.');
    return dot == std::string::npos ? key : key.substr(dot + 1);
}

std::string name_in_column(const std::string& name, std::size_t width) {
    constexpr std::string_view kCut = "...";
    if (name.size() <= width) return name;
    if (width <= kCut.size() + 2) return name.substr(0, width);
    const std::size_t kept = width - kCut.size();
    const std::size_t head = kept / 3;  // the rest for the end
    return name.substr(0, head) + std::string(kCut) + name.substr(name.size() - (kept - head));
}

namespace {

std::string point_name(const std::vector<KeySetting>& coordinates) {
    if (coordinates.empty()) return "base";
    std::string name;
    for (const KeySetting& c : coordinates) {
        if (!name.empty()) name += ',';
        name += short_key(c.first) + "=" + setting_text(c.second);
    }
    // Values are numbers or option words, but a directory name must not hold a separator.
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

// Equal as values of a key: 1 and 1.0 are the same coordinate.
bool same_value(const config::Value& a, const config::Value& b) {
    const auto number = [](const config::Value& v, double& x) {
        if (const auto* d = std::get_if<double>(&v)) return x = *d, true;
        if (const auto* i = std::get_if<std::int64_t>(&v)) return x = static_cast<double>(*i), true;
        return false;
    };
    double x = 0.0, y = 0.0;
    if (number(a, x) && number(b, y)) return x == y;
    return a == b;
}

// [analysis] from/to checked against the frames a point's runs will write: collect's analysis
// would refuse a window past them, or between two of them, after hours of runs.
void check_analysis_window(const CampaignAnalysis& a, const RunPlan& plan,
                           const std::string& what) {
    if (!a.from && !a.to) return;
    if (a.to && plan.control.steady_samples > 0)
        throw InvalidParameter(
            "analysis.to", format_number(*a.to) + " s",
            "no analysis.to where runs stop when steady",
            "time.steady_samples = " + std::to_string(plan.control.steady_samples) + " at " + what +
                ": its runs end where each becomes steady");
    // The frames lie on the output grid; a duration off it ends with one that analyze drops.
    const double interval = plan.frame_interval();
    const double last =
        static_cast<double>(plan.total_steps() / plan.steps_per_output()) * interval;
    const double slack = 1e-6 * interval;
    for (const auto& [key, t] :
         {std::pair{"analysis.from", a.from}, std::pair{"analysis.to", a.to}})
        if (t && *t > last + slack)
            throw InvalidParameter(
                key, format_number(*t) + " s",
                "at most the runs' last frame (" + format_number(last) + " s at " + what + ")",
                "a longer time.duration (or --duration), or an earlier window");
    if (a.from && a.to && std::ceil(*a.from / interval - 1e-6) * interval > *a.to + slack)
        throw InvalidParameter(
            "analysis.to", format_number(*a.to) + " s",
            "a window from analysis.from (" + format_number(*a.from) + " s) that holds a frame",
            "frames are " + format_number(interval) + " s apart at " + what);
}

// The point at `index` (a value of each axis), with its overrides applied and its plan (first
// replicate's seed) validated as a single config's.
CampaignPoint make_point(const Campaign& c, const std::vector<std::size_t>& index,
                         const CampaignScaling& scaling, const EpsilonLookup& epsilon) {
    CampaignPoint p;
    for (std::size_t a = 0; a < c.axes.size(); ++a)
        for (std::size_t k = 0; k < c.axes[a].keys.size(); ++k)
            p.coordinates.emplace_back(c.axes[a].keys[k], c.axes[a].values[index[a]][k]);
    p.name = point_name(p.coordinates);
    p.settings = p.coordinates;
    for (const CampaignOverride& o : c.overrides) {
        const bool applies = std::all_of(o.when.begin(), o.when.end(), [&](const KeySetting& w) {
            return std::any_of(p.coordinates.begin(), p.coordinates.end(),
                               [&](const KeySetting& x) {
                                   return x.first == w.first && same_value(x.second, w.second);
                               });
        });
        if (applies) p.settings.insert(p.settings.end(), o.set.begin(), o.set.end());
    }
    std::vector<KeySetting> seeded = p.settings;
    seeded.emplace_back("run.seed", static_cast<std::int64_t>(c.first_seed));
    const std::string what = "campaign point " + p.name;
    p.plan = config_with_settings(c.base_toml, c.base_source, seeded, what, scaling, epsilon);
    try {
        check_steady_series(p.plan);
    } catch (const InvalidParameter& e) {
        throw e.in_context(what);
    }
    check_analysis_window(c.analysis, p.plan, what);
    const PackingCheck packing = check_packing(p.plan.engine, p.plan.counts);
    if (!packing.ok)
        throw InvalidParameter("species", "the counts of " + what, "a packing that fits",
                               packing.message);
    return p;
}

// A grid too large to plan (a million points took minutes and gigabytes to expand) is refused
// before it is expanded: its size, and what it would cost if every run cost its first point's.
void refuse_unplannable(const Campaign& c, const CampaignScaling& scaling,
                        const EpsilonLookup& epsilon) {
    double points = 1.0;
    std::string product;
    for (const CampaignAxis& a : c.axes) {
        points *= static_cast<double>(a.values.size());
        product += (product.empty() ? "" : " x ") + std::to_string(a.values.size());
    }
    const double runs = points * c.replicates;
    if (points <= kMaxCampaignPoints && runs <= kMaxCampaignRuns) return;
    const CampaignPoint first =
        make_point(c, std::vector<std::size_t>(c.axes.size(), 0), scaling, epsilon);
    const double sphere_steps = static_cast<double>(estimate_resources(first.plan).spheres) *
                                static_cast<double>(first.plan.total_steps());
    throw InvalidParameter(
        "axis",
        product + " points x " + std::to_string(c.replicates) +
            " replicates = " + format_number(runs) + " runs",
        "at most " + format_number(kMaxCampaignPoints) + " points and " +
            format_number(kMaxCampaignRuns) + " runs in one campaign",
        "a run of its first point takes " + format_number(sphere_steps) +
            " sphere-steps, so all would take about " + format_number(sphere_steps * runs) +
            "; split it into campaigns of fewer values, each with its own --out");
}

}  // namespace

CampaignGrid expand_campaign(const Campaign& c, const CampaignScaling& scaling,
                             const EpsilonLookup& epsilon) {
    // What `collect` will ask of the analysis, checked now: hours of runs must not end in an
    // analysis that refuses its options.
    check_observable_names(c.analysis.observables, "analysis.observables");
    AnalysisOptions unused;
    for (const auto& [key, value] : c.analysis.parameters)
        set_analysis_option(unused, key, value, campaign_analysis_parameter_name(key));
    refuse_unplannable(c, scaling, epsilon);
    CampaignGrid grid;
    std::set<std::string> names;
    std::vector<std::size_t> index(c.axes.size(), 0);
    while (true) {
        CampaignPoint p = make_point(c, index, scaling, epsilon);
        if (!names.insert(p.name).second)
            throw InvalidParameter("axis", p.name, "each point once",
                                   "two values of an axis are the same number");
        grid.points.push_back(std::move(p));
        // The next index of the product, the last axis fastest.
        std::size_t a = c.axes.size();
        while (a > 0 && ++index[a - 1] == c.axes[a - 1].values.size())
            index[--a] = 0;
        if (a == 0) break;
    }
    for (std::size_t i = 0; i < grid.points.size(); ++i)
        for (int r = 0; r < c.replicates; ++r) {
            const std::uint64_t seed = c.first_seed + static_cast<std::uint64_t>(r);
            grid.runs.push_back({i, seed, grid.points[i].name + "/seed" + std::to_string(seed),
                                 grid.points[i].plan.control.duration});
        }
    return grid;
}

RunPlan run_plan(const Campaign& c, const CampaignGrid& grid, const CampaignRun& run,
                 const CampaignScaling& scaling, const EpsilonLookup& epsilon) {
    const CampaignPoint& p = grid.points[run.point];
    if (run.seed == c.first_seed) return p.plan;
    std::vector<KeySetting> seeded = p.settings;
    seeded.emplace_back("run.seed", static_cast<std::int64_t>(run.seed));
    return config_with_settings(c.base_toml, c.base_source, seeded, "campaign run " + run.id,
                                scaling, epsilon);
}

}  // namespace rodsea
