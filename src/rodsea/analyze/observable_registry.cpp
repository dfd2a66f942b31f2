#include "rodsea/analyze/observable_registry.hpp"

#include <algorithm>

#include "rodsea/analyze/autocorrelation_observable.hpp"
#include "rodsea/analyze/band_observable.hpp"
#include "rodsea/analyze/corotating_maps_observable.hpp"
#include "rodsea/analyze/defect_observable.hpp"
#include "rodsea/analyze/drift_observable.hpp"
#include "rodsea/analyze/fields_observable.hpp"
#include "rodsea/analyze/flock_defect_observable.hpp"
#include "rodsea/analyze/flock_observable.hpp"
#include "rodsea/analyze/medium_velocity_observable.hpp"
#include "rodsea/analyze/order_parameter_observable.hpp"
#include "rodsea/analyze/pair_correlation_observable.hpp"
#include "rodsea/analyze/segregation_observable.hpp"
#include "rodsea/config/did_you_mean.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

const std::vector<ObservableInfo>& observable_catalogue() {
    static const std::vector<ObservableInfo> catalogue{
        {"order", "P and S per species: time series and steady means"},
        {"pair", "g(r), G(r), G2(r) of polar rods; g(r), G2(r) of apolar medium rods"},
        {"corotating", "g(r,θ), G(r,θ) around polar rods; flock aspect ratio σ_f and N_avg"},
        {"autocorrelation", "C(t), C2(t) and D_r from C = exp(−D_r t)"},
        {"flocks",
         "DBSCAN flocks: N_m(t), <N_m>, histograms, labels per frame; flocks followed in time "
         "(merges, splits, lifetimes, leading rod)"},
        {"segregation", "Σ with its random-mixing baseline subtracted"},
        {"bands",
         "the polar rods' longest density modes: transverse and longitudinal bands relative to "
         "their axis of motion"},
        {"medium_velocity", "medium velocity around polar rods vs distance, and at d"},
        {"drift", "mean velocity of each species; the medium's along the polar rods' heading"},
        {"fields",
         "coarse-grained maps per frame: area fraction, velocity, polarisation, nematic tensor; "
         "the polar-rich interface length"},
        {"defects", "nematic defects of the medium: counts, tracks, pair creation/annihilation"},
        {"flock_defects",
         "distance from flocks to the nearest +1/2 defect and alignment with its orientation"},
    };
    return catalogue;
}

std::string missing_requirement(const std::string& name, const AnalysisSetup& setup) {
    const long long polar = setup.polar_count();
    const long long medium = setup.total_count() - polar;
    const long long rods = polar + setup.count_of(BodyKind::apolar_rod);
    if (name == "order" && rods == 0) return "needs rods (beads have no axis)";
    if (name == "pair" && polar < 2 && setup.count_of(BodyKind::apolar_rod) < 2)
        return "needs at least two polar rods or two apolar rods";
    if (name == "corotating" && polar < 2) return "needs at least two polar rods";
    if (name == "autocorrelation") {
        if (rods == 0) return "needs rods (beads have no axis)";
        if (setup.steady_frames < 2) return "needs at least two frames in the steady window";
    }
    if (name == "flocks" && polar == 0) return "needs polar rods";
    if (name == "bands" && polar < 2) return "needs at least two polar rods";
    if ((name == "segregation" || name == "medium_velocity") && (polar == 0 || medium == 0))
        return "needs polar rods and a medium";
    const long long medium_rods = setup.count_of(BodyKind::apolar_rod);
    if (name == "defects" && medium_rods == 0)
        return "needs a medium of apolar rods (beads have no axis)";
    if (name == "flock_defects" && (polar == 0 || medium_rods == 0))
        return "needs polar rods and a medium of apolar rods";
    return "";
}

std::string species_summary(const AnalysisSetup& setup) {
    std::string text;
    for (const SpeciesInfo& s : setup.species)
        text += (text.empty() ? "" : ", ") + std::to_string(s.count) + " " + to_string(s.kind) +
                " '" + s.name + "'";
    return text + " and " + std::to_string(setup.steady_frames) + " steady frames";
}

void check_observable_names(const std::vector<std::string>& requested, const std::string& key) {
    std::vector<std::string> names;
    for (const ObservableInfo& o : observable_catalogue())
        names.push_back(o.name);
    std::string allowed;
    for (const std::string& n : names)
        allowed += (allowed.empty() ? "" : ", ") + n;
    for (const std::string& n : requested) {
        if (std::find(names.begin(), names.end(), n) != names.end()) continue;
        const auto match = config::closest_match(n, names);
        throw InvalidParameter(key, n, allowed, match ? "did you mean '" + *match + "'?" : "");
    }
}

std::vector<std::string> select_observables(const std::vector<std::string>& requested,
                                            const AnalysisSetup& setup,
                                            std::vector<std::string>* skipped) {
    std::vector<std::string> names;
    for (const ObservableInfo& o : observable_catalogue())
        names.push_back(o.name);
    std::vector<std::string> chosen;
    if (requested.empty()) {
        for (const std::string& n : names) {
            const std::string why = missing_requirement(n, setup);
            if (why.empty())
                chosen.push_back(n);
            else if (skipped)
                skipped->push_back(n + ": " + why);
        }
        return chosen;
    }
    check_observable_names(requested, "--observables");
    for (const std::string& n : requested) {
        const std::string why = missing_requirement(n, setup);
        if (!why.empty())
            throw InvalidParameter(
                "--observables", n, "an observable this run supports",
                "'" + n + "' " + why + "; the run has " + species_summary(setup));
        if (std::find(chosen.begin(), chosen.end(), n) == chosen.end()) chosen.push_back(n);
    }
    return chosen;
}

std::unique_ptr<Observable> make_observable(const std::string& name, const AnalysisSetup& setup,
                                            const AnalysisOptions& options) {
    if (name == "order") return std::make_unique<OrderParameterObservable>(setup);
    if (name == "pair") return std::make_unique<PairCorrelationObservable>(setup, options);
    if (name == "corotating") return std::make_unique<CorotatingMapsObservable>(setup, options);
    if (name == "autocorrelation")
        return std::make_unique<AutocorrelationObservable>(setup, options);
    if (name == "flocks") return std::make_unique<FlockObservable>(setup, options);
    if (name == "segregation") return std::make_unique<SegregationObservable>(setup, options);
    if (name == "bands") return std::make_unique<BandObservable>(setup, options);
    if (name == "medium_velocity")
        return std::make_unique<MediumVelocityObservable>(setup, options);
    if (name == "drift") return std::make_unique<DriftObservable>(setup);
    if (name == "fields") return std::make_unique<FieldsObservable>(setup, options);
    if (name == "defects") return std::make_unique<DefectObservable>(setup, options);
    if (name == "flock_defects") return std::make_unique<FlockDefectObservable>(setup, options);
    throw InvalidParameter("observable", name, "a name from observable_catalogue()");
}

}  // namespace rodsea
