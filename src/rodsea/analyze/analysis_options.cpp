#include "rodsea/analyze/analysis_options.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <variant>
#include <vector>

#include "rodsea/analyze/observable.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

struct OptionKey {
    const char* key;
    std::variant<double AnalysisOptions::*, int AnalysisOptions::*> field;
    const char* unit;
    double lo, hi;  // allowed closed range
    const char* default_text;
    const char* meaning;
};

const std::vector<OptionKey>& option_keys() {
    static const std::vector<OptionKey> keys{
        {"pair.r_max", &AnalysisOptions::pair_r_max, "mm", 0.01, 1e6, "min(L/2, 10 ℓ_p)",
         "range of g(r), G(r), G₂(r) between polar rods"},
        {"pair.bin", &AnalysisOptions::pair_bin, "mm", 1e-3, 1e3, "0.25", "radial bin width"},
        {"pair.medium_r_max", &AnalysisOptions::medium_pair_r_max, "mm", 0.01, 1e6,
         "min(L/2, 15 mm)", "range of g(r), G₂(r) between apolar medium rods"},
        {"corotating.r_max", &AnalysisOptions::corotating_r_max, "mm", 0.01, 1e6, "min(L/2, 5 ℓ_p)",
         "range of g(r,θ), G(r,θ)"},
        {"corotating.r_bins", &AnalysisOptions::corotating_r_bins, "", 2, 10000, "60",
         "radial bins of g(r,θ), G(r,θ)"},
        {"corotating.theta_bins", &AnalysisOptions::corotating_theta_bins, "", 4, 10000, "72",
         "angular bins of g(r,θ), G(r,θ)"},
        {"corotating.contour_level", &AnalysisOptions::contour_level, "", 0.01, 0.99, "0.7",
         "flock contour at this fraction of max g(r,θ) (paper: 70 %)"},
        {"autocorrelation.max_lag", &AnalysisOptions::autocorrelation_max_lag, "s", 0.0, 1e9,
         "half the steady window", "longest lag of C(t), C₂(t)"},
        {"autocorrelation.fit_floor", &AnalysisOptions::autocorrelation_fit_floor, "", 0.01, 0.99,
         "0.2", "D_r is fitted to −ln C = D_r t over the lags where C ≥ this"},
        {"flocks.eps", &AnalysisOptions::flock_eps, "mm", 1e-3, 1e6, "ℓ_p / 2",
         "DBSCAN neighbourhood radius (MODEL.md CHOICE)"},
        {"flocks.min_samples", &AnalysisOptions::flock_min_samples, "", 1, 1e6, "3",
         "DBSCAN core-point count, the point included (MODEL.md CHOICE)"},
        {"segregation.cell", &AnalysisOptions::segregation_cell, "mm", 0.01, 1e6, "2 ℓ_p",
         "side a of the square cells of Σ (MODEL.md CHOICE)"},
        {"segregation.baseline_samples", &AnalysisOptions::segregation_baseline_samples, "", 1, 1e6,
         "200", "random-mixing realisations averaged for the Σ baseline"},
        {"medium_velocity.d", &AnalysisOptions::medium_distance, "mm", 0.0, 1e6, "100",
         "distance at which the medium speed is reported (the paper's d)"},
        {"medium_velocity.r_max", &AnalysisOptions::medium_r_max, "mm", 0.01, 1e6, "min(L/2, d)",
         "range of the medium-velocity profile"},
        {"medium_velocity.bin", &AnalysisOptions::medium_bin, "mm", 1e-3, 1e3, "1",
         "radial bin width of the medium-velocity profile"},
        {"blocks", &AnalysisOptions::blocks, "", 2, 1000, "4",
         "time blocks for the error bars of window averages (D_r, σ_f, N_avg)"},
    };
    return keys;
}

double parse_number(const std::string& key, const std::string& text) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v))
        throw InvalidParameter(key, "'" + text + "'", "a finite number");
    return v;
}

}  // namespace

void set_analysis_option(AnalysisOptions& options, const std::string& key,
                         const std::string& value) {
    const auto& keys = option_keys();
    const auto it =
        std::find_if(keys.begin(), keys.end(), [&](const OptionKey& k) { return key == k.key; });
    if (it == keys.end()) {
        std::vector<std::string> names;
        for (const OptionKey& k : keys)
            names.emplace_back(k.key);
        const auto match = config::closest_match(key, names);
        throw InvalidParameter("--param " + key, "an unknown key",
                               "one of the keys in docs/analysis.md",
                               match ? "did you mean '" + *match + "'?" : "");
    }
    const double v = parse_number(it->key, value);
    require_in_closed_range(it->key, v, it->lo, it->hi, it->unit);
    if (auto* d = std::get_if<double AnalysisOptions::*>(&it->field)) {
        options.** d = v;
    } else {
        const auto i = std::get<int AnalysisOptions::*>(it->field);
        if (v != std::floor(v)) throw InvalidParameter(it->key, value, "a whole number");
        options.*i = static_cast<int>(v);
    }
}

AnalysisOptions resolve_analysis_options(AnalysisOptions o, const AnalysisSetup& setup) {
    const double half = 0.5 * std::min(setup.box.lx, setup.box.ly);
    const double lp = setup.polar_length() > 0.0 ? setup.polar_length() : 4.5;
    const auto pick = [](double& v, double automatic) {
        if (std::isnan(v)) v = automatic;
    };
    if (!std::isnan(o.autocorrelation_max_lag) && o.autocorrelation_max_lag < setup.frame_interval)
        throw InvalidParameter(
            "autocorrelation.max_lag", format_number(o.autocorrelation_max_lag) + " s",
            "at least one frame interval, " + format_number(setup.frame_interval) + " s");
    pick(o.pair_r_max, std::min(half, 10.0 * lp));
    pick(o.medium_pair_r_max, std::min(half, 15.0));
    pick(o.corotating_r_max, std::min(half, 5.0 * lp));
    pick(o.autocorrelation_max_lag,
         0.5 * setup.frame_interval * static_cast<double>(setup.steady_frames));
    pick(o.flock_eps, 0.5 * lp);
    pick(o.segregation_cell, 2.0 * lp);
    pick(o.medium_r_max, std::min(half, std::max(o.medium_distance, o.medium_bin)));
    const std::string half_text = "(0, L/2 = " + format_number(half) + "] mm";
    for (const auto& [key, value] : {std::pair{"pair.r_max", o.pair_r_max},
                                     {"pair.medium_r_max", o.medium_pair_r_max},
                                     {"corotating.r_max", o.corotating_r_max},
                                     {"medium_velocity.r_max", o.medium_r_max},
                                     {"flocks.eps", o.flock_eps}}) {
        // Beyond half the box the minimum image is not unique: a pair would count twice.
        if (value > half) throw InvalidParameter(key, format_number(value) + " mm", half_text);
    }
    if (o.pair_bin >= std::min(o.pair_r_max, o.medium_pair_r_max))
        throw InvalidParameter(
            "pair.bin", format_number(o.pair_bin) + " mm",
            "less than pair.r_max = " + format_number(o.pair_r_max) +
                " mm and pair.medium_r_max = " + format_number(o.medium_pair_r_max) + " mm");
    if (o.medium_bin >= o.medium_r_max)
        throw InvalidParameter(
            "medium_velocity.bin", format_number(o.medium_bin) + " mm",
            "less than medium_velocity.r_max = " + format_number(o.medium_r_max) + " mm");
    if (o.segregation_cell > std::min(setup.box.lx, setup.box.ly))
        throw InvalidParameter(
            "segregation.cell", format_number(o.segregation_cell) + " mm",
            "at most the box side, " + format_number(std::min(setup.box.lx, setup.box.ly)) + " mm");
    return o;
}

std::string analysis_options_reference() {
    std::ostringstream out;
    out << "| key | unit | default | allowed | meaning |\n|---|---|---|---|---|\n";
    for (const OptionKey& k : option_keys())
        out << "| `" << k.key << "` | " << (*k.unit ? k.unit : "–") << " | " << k.default_text
            << " | [" << format_number(k.lo) << ", " << format_number(k.hi) << "] | " << k.meaning
            << " |\n";
    return out.str();
}

}  // namespace rodsea
