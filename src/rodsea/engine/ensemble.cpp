#include "rodsea/engine/ensemble.hpp"

#include <optional>
#include <sstream>
#include <string>

#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/parallel/parallel_ensemble.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

// A blow-up's description, saying which system of the ensemble it was.
BlowUp naming_system(std::size_t m, BlowUp blown) {
    std::ostringstream what;
    what << "system " << m << ": " << blown.what;
    blown.what = what.str();
    return blown;
}

}  // namespace

Ensemble::Ensemble(std::vector<Simulation> systems, BackendOptions options) : options_(options) {
    if (systems.empty()) throw InvalidParameter("systems", "none", "at least one");
    if (options_.threads < 1)
        throw InvalidParameter("threads", std::to_string(options_.threads), ">= 1");
    for (const Simulation& s : systems) {
        params_.push_back(s.parameters());
        step_count_.push_back(s.step_count());
        bounds_.push_back(BlowUpBounds::of(s.parameters(), s.bodies().size()));
    }
    last_.resize(systems.size());
    totals_.resize(systems.size());
    if (options_.backend == BackendKind::cpu) {
        // Each on the ensemble's options (threads, blow-up stop): resumed, so to the last bit.
        for (const Simulation& s : systems)
            cpu_systems_.push_back(
                Simulation::resume(s.parameters(), s.bodies(), s.step_count(), options_));
        return;
    }
    std::vector<std::pair<const SpeciesTable*, BodyState>> states;
    for (std::size_t m = 0; m < systems.size(); ++m) {
        species_.push_back(std::make_unique<SpeciesTable>(SpeciesTable::from(params_[m])));
        states.emplace_back(species_.back().get(), systems[m].bodies());
    }
    stepper_ = make_ensemble_stepper(states, options_);
}

Ensemble::Ensemble(Ensemble&&) noexcept = default;
Ensemble& Ensemble::operator=(Ensemble&&) noexcept = default;
Ensemble::~Ensemble() = default;

const char* Ensemble::backend_name() const {
    return to_string(options_.backend);
}

void Ensemble::step() {
    if (!cpu_systems_.empty()) {
        // Every system steps, as on the GPU, before the first blow-up is reported.
        std::optional<BlowUpError> first_blow_up;
        for (std::size_t m = 0; m < cpu_systems_.size(); ++m) {
            try {
                cpu_systems_[m].step();
            } catch (const BlowUpError& e) {
                if (!first_blow_up)
                    first_blow_up.emplace(naming_system(m, e.blow_up()), e.step(),
                                          cpu_systems_[m].time());
            }
            step_count_[m] = cpu_systems_[m].step_count();
            last_[m] = cpu_systems_[m].last_step();
            totals_[m] = cpu_systems_[m].totals();
        }
        profile_ = {};
        for (const Simulation& s : cpu_systems_) {
            profile_.free_flight += s.profile().free_flight;
            profile_.sphere_update += s.profile().sphere_update;
            profile_.contact_search += s.profile().contact_search;
            profile_.resolution += s.profile().resolution;
            profile_.noise += s.profile().noise;
        }
        if (first_blow_up) throw *first_blow_up;
        return;
    }
    std::vector<StepContext> contexts;
    for (std::size_t m = 0; m < size(); ++m)
        contexts.push_back(step_context(params_[m], step_count_[m] + 1));
    stepper_->step(contexts, last_, profile_);
    for (std::size_t m = 0; m < size(); ++m) {
        ++step_count_[m];
        totals_[m].add(last_[m]);
    }
    for (std::size_t m = 0; m < size(); ++m)
        check_blow_up(m);
}

void Ensemble::check_blow_up(std::size_t m) const {
    if (!options_.stop_on_blow_up) return;
    if (const auto blown = detect_blow_up(bounds_[m], last_[m]))
        throw BlowUpError(naming_system(m, *blown), step_count_[m], time(m));
}

void Ensemble::run(std::uint64_t steps) {
    for (std::uint64_t i = 0; i < steps; ++i)
        step();
}

const BodyState& Ensemble::bodies(std::size_t m) const {
    return cpu_systems_.empty() ? stepper_->bodies(m) : cpu_systems_[m].bodies();
}

std::uint64_t Ensemble::state_hash(std::size_t m) const {
    return rodsea::state_hash(bodies(m), step_count_[m]);
}

}  // namespace rodsea
