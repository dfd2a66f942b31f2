#pragma once
// Every knob of `rodsea analyze`, set with `--param KEY=VALUE`. The initialisers below are the
// defaults (the key table and docs/analysis.md read them); a NaN default is resolved per run from
// the box and the polar rod length (resolve_analysis_options), so one command line serves runs
// of any size. Units: mm and s, as everywhere in rodsea.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rodsea/config/schema.hpp"

namespace rodsea {

struct AnalysisSetup;

struct AnalysisOptions {
    static constexpr double kAuto = std::numeric_limits<double>::quiet_NaN();

    double pair_r_max = kAuto;         // mm; auto: min(L/2, 10 ℓ_p)
    double pair_bin = 0.25;            // mm
    double medium_pair_r_max = kAuto;  // mm; auto: min(L/2, 15 mm)
    double corotating_r_max = kAuto;   // mm; auto: min(L/2, 5 ℓ_p)
    int corotating_r_bins = 60;
    int corotating_theta_bins = 72;
    double contour_level = 0.7;              // fraction of max g(r,θ) (the paper's 70 %)
    double autocorrelation_max_lag = kAuto;  // s; auto: half the steady window
    double autocorrelation_fit_floor = 0.2;  // fit −ln C = D_r t where C ≥ this
    double flock_eps = kAuto;                // mm; auto: ℓ_p / 2 (docs/model.md CHOICE)
    int flock_min_samples = 3;               // docs/model.md CHOICE
    double segregation_cell = kAuto;         // mm; auto: 2 ℓ_p (docs/model.md CHOICE)
    int segregation_baseline_samples = 200;
    double band_threshold = 3.0;     // times the random mean √(π/4N) (CHOICE)
    double medium_distance = 100.0;  // mm, the paper's d
    double medium_r_max = kAuto;     // mm; auto: min(L/2, d)
    double medium_bin = 1.0;         // mm
    int medium_lag = 0;              // frames; 0: the instantaneous velocities
    double field_cell = kAuto;       // mm; auto: min(L/2, ℓ_p)
    int field_every = 1;             // maps of every k-th frame kept
    double interface_level = 0.5;    // polar share of the local area fraction
    double defect_link = kAuto;      // mm; auto: min(L/2, fields.cell)
    double defect_pair = kAuto;      // mm; auto: min(L/2, 2 fields.cell)
    int blocks = 4;                  // time blocks for window-average error bars
};

// The keys, in the config's key-table form (table "pair", name "r_max", ...), in docs order.
const std::vector<config::KeySpec>& analysis_option_keys();

// Sets `key` (e.g. "flocks.eps") from text. Throws InvalidParameter naming the key as the user
// wrote it (`given_as`, e.g. "--param flocks.eps" or "analysis.parameters.flocks.eps"), the value
// and the allowed range, with a did-you-mean for a misspelt key.
void set_analysis_option(AnalysisOptions& options, const std::string& key, const std::string& value,
                         const std::string& given_as);

// Fills the automatic values for this run, unchecked (what a picture takes as its defaults).
AnalysisOptions automatic_analysis_options(AnalysisOptions options, const AnalysisSetup& setup);

// Fills the automatic values for this run and checks the whole set against it (radii up to half
// the box, bins that fit). Throws InvalidParameter naming the key.
AnalysisOptions resolve_analysis_options(AnalysisOptions options, const AnalysisSetup& setup);

// Every key with its value ("pair.r_max=22.5;pair.bin=0.25;..."), exact: two option sets give
// the same text exactly when every value is the same (a cached analysis is reused on it).
std::string analysis_options_text(const AnalysisOptions& options);

// The key reference as a Markdown table (docs/analysis.md), and as lines for `rodsea analyze
// --help`.
std::string analysis_options_reference();
std::string analysis_options_help();

}  // namespace rodsea
