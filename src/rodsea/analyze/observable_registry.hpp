#pragma once
// The observables `rodsea analyze` knows, what each needs from a run, and their construction.
#include <memory>
#include <string>
#include <vector>

#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

struct ObservableInfo {
    std::string name;
    std::string description;
};
const std::vector<ObservableInfo>& observable_catalogue();

// Throws InvalidParameter naming `key` (as the user gave it: "--observables",
// "analysis.observables") for a name not in the catalogue, with the names allowed and a
// did-you-mean.
void check_observable_names(const std::vector<std::string>& names, const std::string& key);

// Why `name` cannot run on this setup ("" when it can).
std::string missing_requirement(const std::string& name, const AnalysisSetup& setup);

// The observables to run: `requested` (empty: every one that applies; those that do not are
// listed in `skipped` with the reason). Throws InvalidParameter for an unknown name or a
// requested observable that needs a species the run lacks.
std::vector<std::string> select_observables(const std::vector<std::string>& requested,
                                            const AnalysisSetup& setup,
                                            std::vector<std::string>* skipped);

std::unique_ptr<Observable> make_observable(const std::string& name, const AnalysisSetup& setup,
                                            const AnalysisOptions& options);

}  // namespace rodsea
