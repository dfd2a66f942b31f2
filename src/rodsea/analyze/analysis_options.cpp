#include "rodsea/analyze/analysis_options.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>
#include <variant>
#include <vector>

#include "rodsea/analysis/histogram_bins.hpp"
#include "rodsea/analyze/observable.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"

namespace rodsea {

namespace {

using config::closed;
using config::integer;
using config::KeySpec;
using config::real;

// Where each key's value lives in AnalysisOptions, in the order of analysis_option_keys().
using Field = std::variant<double AnalysisOptions::*, int AnalysisOptions::*>;
const std::vector<Field> kFields{
    &AnalysisOptions::pair_r_max,
    &AnalysisOptions::pair_bin,
    &AnalysisOptions::medium_pair_r_max,
    &AnalysisOptions::corotating_r_max,
    &AnalysisOptions::corotating_r_bins,
    &AnalysisOptions::corotating_theta_bins,
    &AnalysisOptions::contour_level,
    &AnalysisOptions::autocorrelation_max_lag,
    &AnalysisOptions::autocorrelation_fit_floor,
    &AnalysisOptions::flock_eps,
    &AnalysisOptions::flock_min_samples,
    &AnalysisOptions::segregation_cell,
    &AnalysisOptions::segregation_baseline_samples,
    &AnalysisOptions::band_threshold,
    &AnalysisOptions::medium_distance,
    &AnalysisOptions::medium_r_max,
    &AnalysisOptions::medium_bin,
    &AnalysisOptions::medium_lag,
    &AnalysisOptions::field_cell,
    &AnalysisOptions::field_every,
    &AnalysisOptions::interface_level,
    &AnalysisOptions::defect_link,
    &AnalysisOptions::defect_pair,
    &AnalysisOptions::blocks,
};

std::vector<KeySpec> make_keys() {
    const AnalysisOptions d;  // the defaults
    const auto count = [](int v) { return std::int64_t{v}; };
    return {
        real("pair", "r_max")
            .unit("mm")
            .def_text("min(L/2, 10 ℓ_p)")
            .range(closed(0.01, 1e6))
            .doc("range of g(r), G(r), G₂(r) between polar rods"),
        real("pair", "bin")
            .unit("mm")
            .def(d.pair_bin)
            .range(closed(1e-3, 1e3))
            .doc("radial bin width"),
        real("pair", "medium_r_max")
            .unit("mm")
            .def_text("min(L/2, 15 mm)")
            .range(closed(0.01, 1e6))
            .doc("range of g(r), G₂(r) between apolar medium rods"),
        real("corotating", "r_max")
            .unit("mm")
            .def_text("min(L/2, 5 ℓ_p)")
            .range(closed(0.01, 1e6))
            .doc("range of g(r,θ), G(r,θ)"),
        integer("corotating", "r_bins")
            .def(count(d.corotating_r_bins))
            .integers(2, 10000)
            .doc("radial bins of g(r,θ), G(r,θ)"),
        integer("corotating", "theta_bins")
            .def(count(d.corotating_theta_bins))
            .integers(4, 10000)
            .doc("angular bins of g(r,θ), G(r,θ)"),
        real("corotating", "contour_level")
            .def(d.contour_level)
            .range(closed(0.01, 0.99))
            .doc("flock contour at this fraction of max g(r,θ) (paper: 70 %)"),
        real("autocorrelation", "max_lag")
            .unit("s")
            .def_text("half the steady window")
            .range(closed(0.0, 1e9))
            .doc("longest lag of C(t), C₂(t)"),
        real("autocorrelation", "fit_floor")
            .def(d.autocorrelation_fit_floor)
            .range(closed(0.01, 0.99))
            .doc("D_r is fitted to −ln C = D_r t over the lags where C ≥ this"),
        real("flocks", "eps")
            .unit("mm")
            .def_text("ℓ_p / 2")
            .range(closed(1e-3, 1e6))
            .choice("the paper gives none; docs/model.md §4")
            .doc("DBSCAN neighbourhood radius"),
        integer("flocks", "min_samples")
            .def(count(d.flock_min_samples))
            .integers(1, 1'000'000)
            .choice("the paper gives none; docs/model.md §4")
            .doc("DBSCAN core-point count, the point included"),
        real("segregation", "cell")
            .unit("mm")
            .def_text("2 ℓ_p")
            .range(closed(0.01, 1e6))
            .choice("docs/model.md §4")
            .doc("side a of the square cells of Σ"),
        integer("segregation", "baseline_samples")
            .def(count(d.segregation_baseline_samples))
            .integers(1, 1'000'000)
            .doc("random-mixing realisations averaged for the Σ baseline"),
        real("bands", "threshold")
            .def(d.band_threshold)
            .range(closed(1.0, 100.0))
            .choice("the paper gives none")
            .doc("a band is there where its mode's |ρ_k| is at least this many times the mean "
                 "for random positions, √(π/4N); random positions reach x times it with "
                 "probability exp(−π x²/4): 3 in one frame of 1200, 2 in one of 23. With few "
                 "polar rods no band may reach 3 (|ρ_k| ≤ 1; 18 rods need 0.63)"),
        real("medium_velocity", "d")
            .unit("mm")
            .def(d.medium_distance)
            .range(closed(0.0, 1e6))
            .doc("distance at which the medium speed is reported (the paper's d)"),
        real("medium_velocity", "r_max")
            .unit("mm")
            .def_text("min(L/2, d)")
            .range(closed(0.01, 1e6))
            .doc("range of the medium-velocity profile"),
        real("medium_velocity", "bin")
            .unit("mm")
            .def(d.medium_bin)
            .range(closed(1e-3, 1e3))
            .doc("radial bin width of the medium-velocity profile"),
        integer("medium_velocity", "lag")
            .def(count(d.medium_lag))
            .integers(0, 1'000'000)
            .doc("0: the instantaneous velocities stored in the trajectory, which carry the "
                 "in-plane agitation the plates give every body (tens of mm/s); k: each body's "
                 "velocity from its displacement over k frames (k × output.interval), which "
                 "averages that agitation out and leaves the flow"),
        real("fields", "cell")
            .unit("mm")
            .def_text("min(L/2, ℓ_p)")
            .range(closed(0.01, 1e6))
            .doc("cell side of the coarse-grained fields (cloud-in-cell weights) and of the "
                 "director grid the defects are found on"),
        integer("fields", "every")
            .def(count(d.field_every))
            .integers(1, 1'000'000)
            .doc("keep the maps of every k-th frame in analysis.h5 (the time averages use every "
                 "steady frame)"),
        real("fields", "interface_level")
            .def(d.interface_level)
            .range(closed(0.01, 0.99))
            .doc("polar-rich where the polar rods' share of the local area fraction, "
                 "φ_p / (φ_p + φ_medium), exceeds this; the interface is that contour"),
        real("defects", "link")
            .unit("mm")
            .def_text("min(L/2, fields.cell)")
            .range(closed(1e-3, 1e6))
            .doc("farthest a defect moves between frames and keeps its track"),
        real("defects", "pair")
            .unit("mm")
            .def_text("min(L/2, 2 fields.cell)")
            .range(closed(1e-3, 1e6))
            .doc("farthest apart a ± pair is created or annihilated"),
        integer("", "blocks")
            .def(count(d.blocks))
            .integers(2, 1000)
            .doc("time blocks for the error bars of window averages (D_r, σ_f, N_avg)"),
    };
}

}  // namespace

const std::vector<KeySpec>& analysis_option_keys() {
    static const std::vector<KeySpec> keys = [] {
        std::vector<KeySpec> k = make_keys();
        if (k.size() != kFields.size())
            throw std::logic_error("analysis_option_keys: a key without its field or the reverse");
        return k;
    }();
    return keys;
}

void set_analysis_option(AnalysisOptions& options, const std::string& key, const std::string& value,
                         const std::string& given_as) {
    const std::vector<KeySpec>& keys = analysis_option_keys();
    const auto it =
        std::find_if(keys.begin(), keys.end(), [&](const KeySpec& k) { return key == k.path(); });
    if (it == keys.end()) {
        std::vector<std::string> names;
        for (const KeySpec& k : keys)
            names.push_back(k.path());
        const auto match = config::closest_match(key, names);
        throw InvalidParameter(given_as, "an unknown key", "one of the keys in docs/analysis.md",
                               match ? "did you mean '" + *match + "'?" : "");
    }
    config::Value v;
    try {
        v = config::value_from_text(*it, value);
    } catch (const InvalidParameter&) {  // the same error, under the name the user wrote
        throw InvalidParameter(given_as, value.empty() ? "\"\"" : value, it->allowed_text());
    }
    const Field& field = kFields[static_cast<std::size_t>(it - keys.begin())];
    if (const auto* d = std::get_if<double AnalysisOptions::*>(&field))
        options.** d = std::get<double>(v);
    else
        options.*std::get<int AnalysisOptions::*>(field) =
            static_cast<int>(std::get<std::int64_t>(v));
}

AnalysisOptions automatic_analysis_options(AnalysisOptions o, const AnalysisSetup& setup) {
    const double half = 0.5 * std::min(setup.box.lx, setup.box.ly);
    const double lp = setup.polar_length() > 0.0 ? setup.polar_length() : 4.5;
    const auto pick = [](double& v, double automatic) {
        if (std::isnan(v)) v = automatic;
    };
    pick(o.pair_r_max, std::min(half, 10.0 * lp));
    pick(o.medium_pair_r_max, std::min(half, 15.0));
    pick(o.corotating_r_max, std::min(half, 5.0 * lp));
    pick(o.autocorrelation_max_lag,
         0.5 * setup.frame_interval * static_cast<double>(setup.steady_frames));
    pick(o.flock_eps, 0.5 * lp);
    pick(o.segregation_cell, 2.0 * lp);
    pick(o.medium_r_max, std::min(half, std::max(o.medium_distance, o.medium_bin)));
    // Clamped like the radii above: a small box must not fail on a default the user never set,
    // for an observable not asked for.
    pick(o.field_cell, std::min(half, lp));
    pick(o.defect_link, std::min(half, o.field_cell));
    pick(o.defect_pair, std::min(half, 2.0 * o.field_cell));
    return o;
}

AnalysisOptions resolve_analysis_options(AnalysisOptions o, const AnalysisSetup& setup) {
    const double half = 0.5 * std::min(setup.box.lx, setup.box.ly);
    if (!std::isnan(o.autocorrelation_max_lag) && o.autocorrelation_max_lag < setup.frame_interval)
        throw InvalidParameter(
            "autocorrelation.max_lag", format_number(o.autocorrelation_max_lag) + " s",
            "at least one frame interval, " + format_number(setup.frame_interval) + " s");
    o = automatic_analysis_options(o, setup);
    const std::string half_text = "(0, L/2 = " + format_number(half) + "] mm";
    for (const auto& [key, value] : {std::pair{"pair.r_max", o.pair_r_max},
                                     {"pair.medium_r_max", o.medium_pair_r_max},
                                     {"corotating.r_max", o.corotating_r_max},
                                     {"medium_velocity.r_max", o.medium_r_max},
                                     {"flocks.eps", o.flock_eps},
                                     {"fields.cell", o.field_cell},
                                     {"defects.link", o.defect_link},
                                     {"defects.pair", o.defect_pair}}) {
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
    // Before any frame is read (the compute objects check again as they are built).
    const std::string pair_bin = format_number(o.pair_bin) + " mm";
    require_bins("pair.bin", pair_bin, std::max(o.pair_r_max, o.medium_pair_r_max) / o.pair_bin,
                 "pair.r_max / pair.bin");
    require_bins("medium_velocity.bin", format_number(o.medium_bin) + " mm",
                 o.medium_r_max / o.medium_bin, "medium_velocity.r_max / medium_velocity.bin");
    require_bins("corotating.theta_bins", std::to_string(o.corotating_theta_bins),
                 static_cast<double>(o.corotating_r_bins) * o.corotating_theta_bins,
                 "corotating.r_bins × corotating.theta_bins");
    require_bins(
        "segregation.cell", format_number(o.segregation_cell) + " mm",
        std::ceil(setup.box.lx / o.segregation_cell) * std::ceil(setup.box.ly / o.segregation_cell),
        "the box sides / segregation.cell, squared");
    require_bins("fields.cell", format_number(o.field_cell) + " mm",
                 std::floor(setup.box.lx / o.field_cell) * std::floor(setup.box.ly / o.field_cell),
                 "the box sides / fields.cell, squared");
    return o;
}

std::string analysis_options_text(const AnalysisOptions& options) {
    std::string text;
    const std::vector<KeySpec>& keys = analysis_option_keys();
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const Field& field = kFields[k];
        const auto* d = std::get_if<double AnalysisOptions::*>(&field);
        text += keys[k].path() + "=" +
                (d ? exact_number(options.**d)
                   : std::to_string(options.*std::get<int AnalysisOptions::*>(field))) +
                ";";
    }
    return text;
}

std::string analysis_options_reference() {
    std::ostringstream out;
    out << "| key | unit | default | allowed | meaning |\n|---|---|---|---|---|\n";
    for (const KeySpec& k : analysis_option_keys()) {
        std::string meaning = k.doc;
        if (!k.choice.empty()) meaning += " (docs/model.md CHOICE)";
        out << "| `" << k.path() << "` | " << (k.unit.empty() ? "–" : k.unit) << " | "
            << k.default_doc() << " | " << config::markdown_cell(k.allowed_text()) << " | "
            << config::markdown_cell(meaning) << " |\n";
    }
    return out.str();
}

std::string analysis_options_help() {
    std::ostringstream out;
    for (const KeySpec& k : analysis_option_keys())
        out << "  " << k.path() << ": " << k.doc << "; default " << k.default_doc() << ", allowed "
            << k.allowed_text() << (k.choice.empty() ? "" : " (docs/model.md CHOICE)") << "\n";
    return out.str();
}

}  // namespace rodsea
