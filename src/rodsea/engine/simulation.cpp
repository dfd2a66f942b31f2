#include "rodsea/engine/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

void validate_bodies(const EngineParameters& params, BodyState& bodies, bool fresh_start,
                     double time) {
    if (bodies.size() == 0) throw InvalidParameter("bodies", "0 bodies", ">= 1 body");
    const size_t n = bodies.size();
    if (bodies.position.size() != n || bodies.orientation.size() != n ||
        bodies.velocity.size() != n || bodies.spin.size() != n) {
        throw InvalidParameter("bodies", "arrays of different lengths",
                               "one entry per body in each");
    }
    const StateOrigin origin = fresh_start ? StateOrigin::fresh : StateOrigin::resumed;
    if (const auto p = find_state_problem(params, bodies, time, origin))
        throw InvalidParameter("bodies[" + std::to_string(p->body) + "]." + p->field, p->value,
                               p->allowed, p->detail);
    if (!fresh_start) return;  // a resumed state is taken as it is, to the last bit
    for (Quat& q : bodies.orientation)
        q = normalized(q);
    for (Vec3& x : bodies.position) {
        x.x = PeriodicBox2D::wrap(x.x, params.box.lx);
        x.y = PeriodicBox2D::wrap(x.y, params.box.ly);
    }
}

void check_threads(int threads) {
    if (threads < 1 || threads > kMaxThreads)
        throw InvalidParameter("threads", std::to_string(threads),
                               "an integer in [1, " + std::to_string(kMaxThreads) + "]");
}

template <class T>
void hash_bytes(std::uint64_t& h, const std::vector<T>& data) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    for (size_t i = 0; i < data.size() * sizeof(T); ++i) {
        h ^= bytes[i];
        h *= 1099511628211ULL;
    }
}

}  // namespace

Simulation::Simulation(EngineParameters params, BodyState bodies, BackendOptions options)
    : Simulation(std::move(params), std::move(bodies), 0, options, true) {}

Simulation::Simulation(EngineParameters params, BodyState bodies, std::uint64_t step_count,
                       BackendOptions options, bool fresh_start)
    : params_(std::move(params)), options_(options), step_count_(step_count) {
    validate(params_);
    check_threads(options_.threads);
    validate_bodies(params_, bodies, fresh_start, time());
    bounds_ = BlowUpBounds::of(params_, bodies.size());
    species_ = std::make_unique<SpeciesTable>(SpeciesTable::from(params_));
    backend_ = make_backend(*species_, std::move(bodies), options_);
}

void Simulation::set_threads(int threads) {
    check_threads(threads);
    options_.threads = threads;
    backend_->set_threads(threads);
}

Simulation Simulation::resume(EngineParameters params, BodyState bodies, std::uint64_t step_count,
                              BackendOptions options) {
    return Simulation(std::move(params), std::move(bodies), step_count, options, false);
}

Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
Simulation::~Simulation() = default;

StepContext step_context(const EngineParameters& params, std::uint64_t step) {
    StepContext context;
    context.dt = params.dt;
    context.gravity = params.drive.gravity;
    context.box = {params.box.lx, params.box.ly};
    context.step = step;
    context.plate_motion = params.drive.motion();
    context.plates =
        physics::plate_state(context.plate_motion, static_cast<double>(step) * params.dt);
    context.approach_tolerance = params.approach_tolerance;
    context.max_sweeps = params.max_sweeps;
    context.noise_epsilon = params.noise_epsilon;
    context.noise_mode = params.noise_mode;
    context.seed = params.seed;
    return context;
}

void Simulation::step() {
    run(1);
}

void Simulation::run(std::uint64_t steps) {
    std::vector<StepContext> contexts;
    while (steps > 0) {
        const std::uint64_t length = std::min(steps, kStepsPerRun);
        contexts.clear();
        for (std::uint64_t k = 1; k <= length; ++k)
            contexts.push_back(step_context(params_, step_count_ + k));
        const StepsDone done =
            backend_->run_steps(contexts, options_.stop_on_blow_up ? &bounds_ : nullptr, profile_);
        step_count_ += done.steps;
        steps -= done.steps;
        last_ = done.last;
        totals_.add(done.tally);
        if (done.blew_up) {
            const std::optional<BlowUp> blown = detect_blow_up(bounds_, last_);
            throw BlowUpError(*blown, step_count_, time());
        }
    }
}

double Simulation::kinetic_energy() const {
    double e = 0.0;
    const BodyState& state = bodies();
    for (size_t b = 0; b < state.size(); ++b) {
        const Shape& shape = params_.species[state.species[b]].shape;
        const Vec3 w = rotate(conjugate(state.orientation[b]), state.spin[b]);
        const Vec3& i = shape.principal_inertia;
        e += 0.5 * shape.mass * norm2(state.velocity[b]) +
             0.5 * (i.x * w.x * w.x + i.y * w.y * w.y + i.z * w.z * w.z);
    }
    return e;
}

Vec3 Simulation::linear_momentum() const {
    Vec3 p;
    const BodyState& state = bodies();
    for (size_t b = 0; b < state.size(); ++b)
        p += params_.species[state.species[b]].shape.mass * state.velocity[b];
    return p;
}

Vec3 Simulation::angular_momentum(const Vec3& about) const {
    Vec3 l;
    const BodyState& state = bodies();
    for (size_t b = 0; b < state.size(); ++b) {
        const Shape& shape = params_.species[state.species[b]].shape;
        const Quat& q = state.orientation[b];
        const Vec3 wb = rotate(conjugate(q), state.spin[b]);
        const Vec3& i = shape.principal_inertia;
        l += rotate(q, Vec3{i.x * wb.x, i.y * wb.y, i.z * wb.z}) +
             shape.mass * cross(state.position[b] - about, state.velocity[b]);
    }
    return l;
}

std::uint64_t Simulation::state_hash() const {
    return rodsea::state_hash(bodies(), step_count_);
}

std::uint64_t state_hash(const BodyState& state, std::uint64_t step_count) {
    std::uint64_t h = 14695981039346656037ULL;
    hash_bytes(h, std::vector<std::uint64_t>{step_count});
    hash_bytes(h, state.species);
    hash_bytes(h, state.position);
    hash_bytes(h, state.orientation);
    hash_bytes(h, state.velocity);
    hash_bytes(h, state.spin);
    return h;
}

}  // namespace rodsea
