#include "rodsea/engine/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>

#include "rodsea/engine/free_flight.hpp"
#include "rodsea/engine/plate_noise.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

class StageTimer {
  public:
    explicit StageTimer(double& sink) : sink_(sink), start_(std::chrono::steady_clock::now()) {}
    ~StageTimer() {
        sink_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

  private:
    double& sink_;
    std::chrono::steady_clock::time_point start_;
};

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void validate_bodies(const EngineParameters& params, BodyState& bodies, bool fresh_start) {
    if (bodies.size() == 0) throw InvalidParameter("bodies", "0 bodies", ">= 1 body");
    const size_t n = bodies.size();
    if (bodies.position.size() != n || bodies.orientation.size() != n ||
        bodies.velocity.size() != n || bodies.spin.size() != n) {
        throw InvalidParameter("bodies", "arrays of different lengths",
                               "one entry per body in each");
    }
    const PlateState plates = plate_state(params.drive, 0.0);
    for (size_t b = 0; b < n; ++b) {
        const std::string key = "bodies[" + std::to_string(b) + "]";
        if (bodies.species[b] >= params.species.size()) {
            throw InvalidParameter(key + ".species", std::to_string(bodies.species[b]),
                                   "[0, " + std::to_string(params.species.size() - 1) + "]");
        }
        const Quat& q = bodies.orientation[b];
        const double qn = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
        if (!std::isfinite(qn) || qn == 0.0) {
            throw InvalidParameter(key + ".orientation", "a zero or non-finite quaternion",
                                   "a non-zero quaternion");
        }
        // A resumed state is taken as it is: renormalising would change its last bits.
        if (fresh_start) bodies.orientation[b] = normalized(q);
        if (!finite(bodies.position[b]) || !finite(bodies.velocity[b]) || !finite(bodies.spin[b])) {
            throw InvalidParameter(key, "a non-finite position, velocity or spin", "finite values");
        }
        if (!fresh_start) continue;  // a resumed body may touch a plate
        const Species& sp = params.species[bodies.species[b]];
        for (size_t s = 0; s < sp.shape.sphere_count(); ++s) {
            const double z =
                bodies.position[b].z + rotate(bodies.orientation[b], sp.shape.offsets[s]).z;
            const double r = sp.shape.radii[s];
            if (z - r < plates.base_z || z + r > plates.lid_z) {
                throw InvalidParameter(
                    key + ".position.z", format_number(bodies.position[b].z) + " mm",
                    "every sphere between the base (z = " + format_number(plates.base_z) +
                        " mm at t = 0) and the lid (z = " + format_number(plates.lid_z) + " mm)",
                    std::string(to_string(sp.kind)) + " sphere " + std::to_string(s) +
                        " spans z = " + format_number(z - r) + " .. " + format_number(z + r) +
                        " mm");
            }
        }
    }
    for (Vec3& x : bodies.position) {
        x.x = PeriodicBox2D::wrap(x.x, params.box.lx);
        x.y = PeriodicBox2D::wrap(x.y, params.box.ly);
    }
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

Simulation::Simulation(EngineParameters params, BodyState bodies)
    : params_(std::move(params)), bodies_(std::move(bodies)) {
    validate(params_);
    validate_bodies(params_, bodies_, true);
    spheres_.assign(bodies_, params_.species);
    spheres_.update_positions(bodies_, params_.species);
}

Simulation::Simulation(EngineParameters params, BodyState bodies, std::uint64_t step_count, Resumed)
    : params_(std::move(params)), bodies_(std::move(bodies)), step_count_(step_count) {
    validate(params_);
    validate_bodies(params_, bodies_, false);
    spheres_.assign(bodies_, params_.species);
    spheres_.update_positions(bodies_, params_.species);
}

Simulation Simulation::resume(EngineParameters params, BodyState bodies, std::uint64_t step_count) {
    return Simulation(std::move(params), std::move(bodies), step_count, Resumed{});
}

void Simulation::step() {
    double fastest = 0.0;  // bound on any sphere's speed in the plane in this step (mm/s)
    {
        StageTimer t(profile_.free_flight);
        fastest = advance_free_flight(bodies_, params_.species, params_.box, params_.drive.gravity,
                                      params_.dt, threads_);
    }
    ++step_count_;
    const PlateState plates = plate_state(params_.drive, time());
    {
        StageTimer t(profile_.sphere_update);
        spheres_.update_positions(bodies_, params_.species, threads_);
    }
    ContactSearchStats found;
    {
        StageTimer t(profile_.contact_search);
        found = finder_.find(spheres_, bodies_, params_, plates, contacts_, threads_,
                             fastest * params_.dt);
    }
    ResolutionStats resolved;
    {
        StageTimer t(profile_.resolution);
        inverse_inertia_.update_for(contacts_, bodies_, params_.species);
        plate_hits_.clear();
        resolved = resolver_.resolve(contacts_, bodies_, inverse_inertia_, plates.velocity_z,
                                     params_, plate_hits_, threads_);
        plate_projection_.apply(contacts_, bodies_, spheres_);
    }
    size_t kicks = 0;
    {
        StageTimer t(profile_.noise);
        kicks = apply_plate_noise(plate_hits_, bodies_, params_.species, params_.noise_epsilon,
                                  params_.seed, step_count_, threads_);
    }

    last_ = {found.body_contacts,       found.plate_contacts,
             resolved.sweeps,           resolved.impulses,
             resolved.body_collisions,  resolved.plate_collisions,
             resolved.unresolved,       kicks,
             found.max_overlap_fraction};
    totals_.impulses += resolved.impulses;
    totals_.unresolved += resolved.unresolved;
    totals_.noise_kicks += kicks;
    totals_.max_sweeps = std::max(totals_.max_sweeps, resolved.sweeps);
    totals_.max_overlap_fraction =
        std::max(totals_.max_overlap_fraction, found.max_overlap_fraction);
}

void Simulation::set_threads(int threads) {
    if (threads < 1) throw InvalidParameter("threads", std::to_string(threads), ">= 1");
    threads_ = threads;
}

void Simulation::run(std::uint64_t steps) {
    for (std::uint64_t i = 0; i < steps; ++i)
        step();
}

double Simulation::kinetic_energy() const {
    double e = 0.0;
    for (size_t b = 0; b < bodies_.size(); ++b) {
        const Shape& shape = params_.species[bodies_.species[b]].shape;
        const Vec3 w = rotate(conjugate(bodies_.orientation[b]), bodies_.spin[b]);
        const Vec3& i = shape.principal_inertia;
        e += 0.5 * shape.mass * norm2(bodies_.velocity[b]) +
             0.5 * (i.x * w.x * w.x + i.y * w.y * w.y + i.z * w.z * w.z);
    }
    return e;
}

Vec3 Simulation::linear_momentum() const {
    Vec3 p;
    for (size_t b = 0; b < bodies_.size(); ++b)
        p += params_.species[bodies_.species[b]].shape.mass * bodies_.velocity[b];
    return p;
}

Vec3 Simulation::angular_momentum(const Vec3& about) const {
    Vec3 l;
    for (size_t b = 0; b < bodies_.size(); ++b) {
        const Shape& shape = params_.species[bodies_.species[b]].shape;
        const Quat& q = bodies_.orientation[b];
        const Vec3 wb = rotate(conjugate(q), bodies_.spin[b]);
        const Vec3& i = shape.principal_inertia;
        l += rotate(q, Vec3{i.x * wb.x, i.y * wb.y, i.z * wb.z}) +
             shape.mass * cross(bodies_.position[b] - about, bodies_.velocity[b]);
    }
    return l;
}

std::uint64_t Simulation::state_hash() const {
    std::uint64_t h = 14695981039346656037ULL;
    hash_bytes(h, std::vector<std::uint64_t>{step_count_});
    hash_bytes(h, bodies_.species);
    hash_bytes(h, bodies_.position);
    hash_bytes(h, bodies_.orientation);
    hash_bytes(h, bodies_.velocity);
    hash_bytes(h, bodies_.spin);
    return h;
}

}  // namespace rodsea
