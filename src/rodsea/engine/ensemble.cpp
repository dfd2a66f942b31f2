#include "rodsea/engine/ensemble.hpp"

#include <algorithm>
#include <exception>
#include <optional>
#include <sstream>
#include <string>

#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/cpu/detail/parallel.hpp"
#include "rodsea/engine/parallel/parallel_ensemble.hpp"
#include "rodsea/engine/work_shares.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

// Steps between looks at what each system's steps cost: about 0.1 s of wall time for the
// 38 mm boxes of a campaign, long enough for the clock's jitter to average out, short enough
// to follow a system that jams.
constexpr std::uint64_t kStepsBetweenLooks = 1000;
// A new deal must shorten the ensemble's step by this much (work_shares.hpp, better_deal):
// costs measured over a window jitter by a few per cent.
constexpr double kWorthMoving = 0.95;

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
    last_run_.resize(systems.size());
    blown_.resize(systems.size());
    if (options_.backend == BackendKind::cpu) {
        // Each on the ensemble's options (threads, blow-up stop): resumed, so to the last bit.
        for (const Simulation& s : systems)
            cpu_systems_.push_back(
                Simulation::resume(s.parameters(), s.bodies(), s.step_count(), options_));
        share_threads();
        return;
    }
    std::vector<const BodyState*> states;
    for (std::size_t m = 0; m < systems.size(); ++m) {
        species_.push_back(std::make_unique<SpeciesTable>(SpeciesTable::from(params_[m])));
        states.push_back(&systems[m].bodies());
    }
    make_stepper(states);
}

void Ensemble::make_stepper(const std::vector<const BodyState*>& states) {
    std::vector<std::pair<const SpeciesTable*, BodyState>> systems;
    for (std::size_t m = 0; m < states.size(); ++m)
        systems.emplace_back(species_[m].get(), *states[m]);
    stepper_ = make_ensemble_stepper(systems, options_);
}

void Ensemble::retire(const std::vector<std::size_t>& systems) {
    std::vector<bool> keep(size(), true);
    for (std::size_t m : systems) {
        if (m >= size())
            throw InvalidParameter("system", std::to_string(m),
                                   "an index below the ensemble's " + std::to_string(size()));
        keep[m] = false;
    }
    // The data-parallel stepper holds no state between steps but the bodies: a new one over the
    // systems kept steps them on as the old one would have.
    std::vector<BodyState> kept_states;
    if (stepper_)
        for (std::size_t m = 0; m < size(); ++m)
            if (keep[m]) kept_states.push_back(stepper_->bodies(m));
    std::size_t next = 0;
    for (std::size_t m = 0; m < size(); ++m) {
        if (!keep[m]) continue;
        params_[next] = std::move(params_[m]);
        step_count_[next] = step_count_[m];
        bounds_[next] = bounds_[m];
        last_[next] = last_[m];
        totals_[next] = totals_[m];
        last_run_[next] = last_run_[m];
        blown_[next] = std::move(blown_[m]);
        if (!cpu_systems_.empty()) cpu_systems_[next] = std::move(cpu_systems_[m]);
        if (!step_cost_.empty()) step_cost_[next] = step_cost_[m];
        if (!species_.empty()) species_[next] = std::move(species_[m]);
        ++next;
    }
    params_.resize(next);
    step_count_.resize(next);
    bounds_.resize(next);
    last_.resize(next);
    totals_.resize(next);
    last_run_.resize(next);
    blown_.resize(next);
    if (!step_cost_.empty()) step_cost_.resize(next);
    if (!cpu_systems_.empty()) {
        cpu_systems_.erase(cpu_systems_.begin() + next, cpu_systems_.end());
        share_threads();  // fewer systems side by side: more threads each
    }
    if (!stepper_) return;
    stepper_.reset();  // before the species tables of the systems retired
    species_.resize(next);
    if (next == 0) return;
    std::vector<const BodyState*> states;
    for (const BodyState& b : kept_states)
        states.push_back(&b);
    make_stepper(states);
}

void Ensemble::set_threads(int threads) {
    if (threads < 1) throw InvalidParameter("threads", std::to_string(threads), ">= 1");
    options_.threads = threads;
    share_threads();
    if (stepper_) stepper_->set_threads(threads);
}

Ensemble::Ensemble(Ensemble&&) noexcept = default;
Ensemble& Ensemble::operator=(Ensemble&&) noexcept = default;
Ensemble::~Ensemble() = default;

const char* Ensemble::backend_name() const {
    return to_string(options_.backend);
}

void Ensemble::step() {
    run(1);
}

void Ensemble::run(std::uint64_t steps) {
    for (StepTally& t : last_run_)
        t = {};
    if (size() == 0) return;
    if (cpu_systems_.empty()) {
        run_on_stepper(steps);
        return;
    }
    for (std::uint64_t i = 0; i < steps; ++i)
        step_cpu_systems();
}

void Ensemble::run_on_stepper(std::uint64_t steps) {
    std::vector<StepContext> contexts;
    std::vector<StepsDone> done;
    while (steps > 0) {
        const std::uint64_t length = std::min(steps, Simulation::kStepsPerRun);
        contexts.clear();
        for (std::uint64_t k = 1; k <= length; ++k)
            for (std::size_t m = 0; m < size(); ++m)
                contexts.push_back(step_context(params_[m], step_count_[m] + k));
        stepper_->run(contexts, length, options_.stop_on_blow_up ? &bounds_ : nullptr, done,
                      profile_);
        std::optional<std::size_t> first_blown;
        for (std::size_t m = 0; m < size(); ++m) {
            step_count_[m] += done[m].steps;
            last_[m] = done[m].last;
            totals_[m].add(done[m].tally);
            last_run_[m].add(done[m].tally);
            blown_[m].reset();
            if (done[m].blew_up) {
                blown_[m] = detect_blow_up(bounds_[m], last_[m]);
                if (!first_blown) first_blown = m;
            }
        }
        if (first_blown)
            throw BlowUpError(naming_system(*first_blown, *blown_[*first_blown]),
                              step_count_[*first_blown], time(*first_blown));
        steps -= length;
    }
}

void Ensemble::step_cpu_systems() {
    const std::size_t n = cpu_systems_.size();
    // Every system steps, as on the GPU, before the first blow-up is reported.
    std::vector<std::exception_ptr>& failed = failed_;
    failed.assign(n, nullptr);  // no allocation after the first step
    const auto step_one = [&](std::size_t m) {
        blown_[m].reset();
        try {
            cpu_systems_[m].step();
        } catch (const BlowUpError& e) {
            blown_[m] = e.blow_up();
        } catch (...) {
            failed[m] = std::current_exception();
        }
    };
    cpu::for_each_in_parallel(shares_.size(), static_cast<int>(shares_.size()),
                              [&](std::size_t worker) {
                                  for (std::size_t m : shares_[worker])
                                      step_one(m);
                              });
    profile_ = {};
    for (std::size_t m = 0; m < n; ++m) {
        const Simulation& s = cpu_systems_[m];
        step_count_[m] = s.step_count();
        last_[m] = s.last_step();
        last_run_[m].add(last_[m]);
        totals_[m] = s.totals();
        profile_.free_flight += s.profile().free_flight;
        profile_.sphere_update += s.profile().sphere_update;
        profile_.contact_search += s.profile().contact_search;
        profile_.resolution += s.profile().resolution;
        profile_.noise += s.profile().noise;
        profile_.whole_steps += s.profile().whole_steps;
    }
    if (shares_.size() > 1 && ++steps_since_look_ >= kStepsBetweenLooks) reshare_by_measured_cost();
    for (const std::exception_ptr& e : failed)  // every system has stepped and been counted
        if (e) std::rethrow_exception(e);
    for (std::size_t m = 0; m < n; ++m)
        if (blown_[m]) throw BlowUpError(naming_system(m, *blown_[m]), step_count_[m], time(m));
}

int Ensemble::systems_side_by_side() const {
    return static_cast<int>(
        workers_side_by_side(static_cast<std::size_t>(options_.threads), cpu_systems_.size()));
}

int Ensemble::threads_per_system() const {
    return systems_side_by_side() > 1 ? 1 : options_.threads;
}

void Ensemble::share_threads() {
    for (Simulation& s : cpu_systems_)
        s.set_threads(threads_per_system());
    // Until their steps have been timed, the systems cost what their spheres do; after a system
    // retires or the threads change, what they cost at the last look.
    std::vector<double> cost = step_cost_;
    if (cost.size() != cpu_systems_.size()) {
        cost.clear();
        for (const Simulation& s : cpu_systems_)
            cost.push_back(static_cast<double>(s.spheres().size()));
    }
    shares_ = share_by_cost(cost, static_cast<std::size_t>(systems_side_by_side()));
    stage_time_at_look_.clear();
    for (const Simulation& s : cpu_systems_)
        stage_time_at_look_.push_back(s.profile().total());
    steps_since_look_ = 0;
}

void Ensemble::reshare_by_measured_cost() {
    step_cost_.assign(cpu_systems_.size(), 0.0);
    for (std::size_t m = 0; m < cpu_systems_.size(); ++m) {
        const double now = cpu_systems_[m].profile().total();
        step_cost_[m] = (now - stage_time_at_look_[m]) / static_cast<double>(steps_since_look_);
        stage_time_at_look_[m] = now;
    }
    steps_since_look_ = 0;
    if (std::optional<WorkShares> dealt = better_deal(shares_, step_cost_, kWorthMoving))
        shares_ = std::move(*dealt);
}

const BodyState& Ensemble::bodies(std::size_t m) const {
    return cpu_systems_.empty() ? stepper_->bodies(m) : cpu_systems_[m].bodies();
}

std::uint64_t Ensemble::state_hash(std::size_t m) const {
    return rodsea::state_hash(bodies(m), step_count_[m]);
}

}  // namespace rodsea
