#include "rodsea/engine/cpu/coasting_backend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rodsea/engine/physics/coasting.hpp"
#include "rodsea/engine/physics/free_flight.hpp"
#include "rodsea/engine/physics/sphere_placement.hpp"
#include "rodsea/engine/stage_timer.hpp"

namespace rodsea::cpu {

namespace {

// A coast shorter than this many steps is not begun: the bounds cost about what a dozen steps of
// a body do (docs/performance.md, "Coasting").
constexpr std::uint64_t kShortestCoast = 16;
// A body that could not coast tries again this many steps later (it touches something about
// every other step, or flies close to a plate or a neighbour).
constexpr std::uint64_t kRetrySteps = 8;
// The plate scan looks no further ahead (2¹⁸ steps, 0.33 s at 1.25 µs; a body falls between
// the plates in milliseconds).
constexpr std::uint64_t kPlateHorizon = std::uint64_t{1} << 18;
// T saturates here: a step whose speed bound is not finite (a blow-up) wakes every body.
constexpr std::uint64_t kTravelSaturated = std::uint64_t{1} << 62;
// A promise: this many times the body's speed bound, plus kPromiseSlack (mm/s). Higher promises
// break less often and give shorter coasts; a medium rod's speed bound is 10-20 mm/s, most
// collisions change it by less than that.
constexpr double kPromiseFactor = 1.5;
constexpr double kPromiseSlack = 10.0;
constexpr double kNoPromise = std::numeric_limits<double>::infinity();
// A coast relies on its neighbours' promises for at most this long (2 ms, 1600 steps of 1.25 µs):
// its own speed in space is bounded by its start's plus g times this.
constexpr double kLongestReliance = 2e-3;
// A coast relies on its calm neighbours' free flights for at most this long (10 ms, 8000 steps):
// it bounds how fast they can be approaching a plate.
constexpr double kLongestFlight = 1e-2;
// A neighbour with no contact for this many steps is calm: relied on to keep its free flight.
// The polar rods, which touch a plate about every other step, never are.
constexpr std::uint64_t kCalmSteps = 32;

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
    return a >= kTravelSaturated - std::min(b, kTravelSaturated) ? kTravelSaturated : a + b;
}

// Whole steps strictly inside `seconds`, at least 0, at most 2⁶²: a gap closing at a bounded speed
// stays open at the end of each of them. NaN gives 0.
std::uint64_t steps_within(double seconds, double dt) {
    const double n = seconds / dt * (1.0 - 1e-12);
    if (!(n >= 1.0)) return 0;
    if (n >= 4e18) return kTravelSaturated;
    return static_cast<std::uint64_t>(n);
}

// The first time τ ≥ 0 at which |d + w τ| − R τ might reach `apart`: solves |d + w τ| = apart +
// R τ, squared: (|w|² − R²) τ² + 2 (d·w − apart R) τ + (|d|² − apart²) = 0, the smaller positive
// root (the stable form 2C / (−B + √(B² − 4AC))), shortened by 10⁻⁶ for its rounding. Infinity
// when it never does; 0 when it does already; NaN stays NaN.
double first_reach(const Vec3& d, const Vec3& w, double turn, double apart) {
    const double distance = norm(d);
    if (!(distance > apart)) return distance == distance ? 0.0 : distance;
    const double a = norm2(w) - turn * turn;
    const double half_b = dot(d, w) - apart * turn;
    const double c = (distance - apart) * (distance + apart);
    const double discriminant = half_b * half_b - a * c;
    if (!(discriminant >= 0.0) || (a >= 0.0 && half_b >= 0.0))
        return discriminant == discriminant ? std::numeric_limits<double>::infinity()
                                            : discriminant;
    const double denominator = -half_b + std::sqrt(discriminant);
    if (!(denominator > 0.0)) return std::numeric_limits<double>::infinity();
    return c / denominator * (1.0 - 1e-6);
}

}  // namespace

// How fast body b's sphere centres can move about its centre, mm/s: reach times |ω × u| for a
// body whose spheres lie on its symmetry axis u (regular precession keeps it), reach times a
// bound on |ω| otherwise.
double CoastingBackend::turn_rate(std::uint32_t b, const Quat& q, const Vec3& w) const {
    const std::uint32_t k = bodies_.species[b];
    const physics::Rotor& rotor = species_.rotor[k];
    const int axis = species_.sphere_axis[k];
    const double turning = axis >= 0 && rotor.axis == axis
                               ? norm(cross(w, rotated_axis(q, axis)))
                               : std::sqrt(physics::spin_bound2(rotor, q, w));
    return std::sqrt(species_.reach2[k]) * turning;
}

// A neighbour relied on by the speed it promises: its speeds, the promise it keeps or would make,
// how far it may have moved since its spheres were placed. False if it already broke its
// promise (after this step's impulses) or would, coasting on.
bool CoastingBackend::promised_speeds(std::uint32_t j, std::uint64_t s, double dt, double g,
                                      Near& n) const {
    if (coasting_[j]) {
        // Its spheres are where they were placed, at most this far from where it is: in the
        // plane at its constant speed, in space at its start's plus g τ.
        const double since_placed = static_cast<double>(s - placed_step_[j]) * dt;
        const double fallen = g * static_cast<double>(s - since_[j]) * dt;
        n.moved_planar = speed_[j] * since_placed;
        n.moved_space = (speed3_[j] + fallen) * since_placed;
        // What it may reach while relied on, if it coasts on.
        n.planar = speed_[j];
        n.space = speed3_[j] + fallen + g * kLongestReliance;
    } else {
        const Speeds now = speed_bounds(j);
        n.planar = now.planar;
        n.space = now.space;
    }
    if (promise_[j] != kNoPromise) {
        if (!(n.planar <= promise_[j] && n.space <= promise3_[j])) return false;
        n.planar = promise_[j];
        n.space = promise3_[j];
    } else {
        n.planar = kPromiseFactor * n.planar + kPromiseSlack;
        n.space = kPromiseFactor * n.space + kPromiseSlack + g * kLongestReliance;
    }
    return true;
}

CoastingBackend::CoastingBackend(const SpeciesTable& species, BodyState bodies, int threads)
    : species_(species), bodies_(std::move(bodies)), threads_(threads), finder_(kSkin) {
    const std::size_t n = bodies_.size();
    coasting_.assign(n, 0);
    since_.assign(n, 0);
    plate_wake_.assign(n, 0);
    plate_known_.assign(n, 0);
    neighbour_wake_.assign(n, 0);
    travel_wake_.assign(n, 0);
    placed_step_.assign(n, 0);
    next_try_.assign(n, 0);
    speed_.assign(n, 0.0);
    speed3_.assign(n, 0.0);
    generation_.assign(n, 0);
    promise_.assign(n, kNoPromise);
    promise3_.assign(n, kNoPromise);
    watchers_.assign(n, {});
    flight_watchers_.assign(n, {});
    touched_at_.assign(n, 0);
    touched_.assign(n, 0);
    failures_.assign(n, 0);
    near_slot_.assign(n, 0);
    spheres_.assign(bodies_.species, species_);
    spheres_.update_positions(bodies_.view(), species_, 1);
}

void CoastingBackend::fly_to(std::uint32_t b, std::uint64_t step, Vec3& x, Vec3& v, Quat& q,
                             Vec3& w) const {
    x = bodies_.position[b];
    v = bodies_.velocity[b];
    q = bodies_.orientation[b];
    w = bodies_.spin[b];
    if (step > since_[b])
        physics::fly_for(x, v, q, w, species_.rotor[bodies_.species[b]], step - since_[b],
                         flight_.dt, flight_.gravity, flight_.box);
}

CoastingBackend::Speeds CoastingBackend::speed_bounds(std::uint32_t b) const {
    const std::uint32_t k = bodies_.species[b];
    const physics::PlanarSpeed2 p =
        physics::planar_speed2(bodies_.velocity[b], bodies_.orientation[b], bodies_.spin[b],
                               species_.rotor[k], species_.reach2[k]);
    const double turn = std::sqrt(p.turn2);
    return {std::sqrt(p.drift2) + turn, norm(bodies_.velocity[b]) + turn};
}

void CoastingBackend::wake_and_fly(const StepContext& context, double& fastest) {
    const std::uint64_t s = context.step;
    const BodyView bodies = bodies_.view();
    const auto awake = static_cast<std::ptrdiff_t>(awake_.size());
    // The planar speed bound of this step (free_flight.cpp): the awake bodies' from their state,
    // the coasting ones' kept from their coast's start (constant in free flight).
    double drift2 = 0.0, turn2 = 0.0;
    // clang-format off
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1) \
    reduction(max : drift2, turn2)
    // clang-format on
    for (std::ptrdiff_t i = 0; i < awake; ++i) {
        const std::uint32_t b = awake_[static_cast<std::size_t>(i)];
        const std::uint32_t k = bodies.species[b];
        const physics::PlanarSpeed2 p =
            physics::planar_speed2(bodies.velocity[b], bodies.orientation[b], bodies.spin[b],
                                   species_.rotor[k], species_.reach2[k]);
        drift2 = std::max(drift2, p.drift2);
        turn2 = std::max(turn2, p.turn2);
        const double turn = std::sqrt(p.turn2);
        speed_[b] = std::sqrt(p.drift2) + turn;
        speed3_[b] = norm(bodies.velocity[b]) + turn;
    }
    fastest = std::max(std::sqrt(drift2) + std::sqrt(turn2), coasting_fastest_);
    const double units = fastest * context.dt / kTravelUnit;
    travel_ = saturating_add(
        travel_, units < 1e15 ? static_cast<std::uint64_t>(std::ceil(units)) : kTravelSaturated);

    // A body faster than it promised wakes every coast that relied on the promise, before
    // anything moves: until this step it kept the promise, so they were safe until now.
    broken_.clear();
    for (const std::uint32_t b : awake_)
        if (!(speed_[b] <= promise_[b]) || !(speed3_[b] <= promise3_[b])) broken_.push_back(b);
    for (const std::uint32_t j : broken_) {
        for (const Watch& w : watchers_[j])
            if (coasting_[w.body] && generation_[w.body] == w.generation)
                coasting_[w.body] = 2;  // wakes below
        watchers_[j].clear();
        promise_[j] = promise3_[j] = kNoPromise;
    }

    // Wake what might touch something at this step's end; the rest coasts on.
    double still_coasting = 0.0;
    awake_.clear();
    for (std::uint32_t b = 0; b < bodies_.size(); ++b) {
        if (coasting_[b]) {
            const bool by_promise = coasting_[b] == 2;
            const bool by_plate = s >= plate_wake_[b], by_neighbour = s >= neighbour_wake_[b],
                       by_travel = travel_ >= travel_wake_[b];
            if (!by_promise && !by_plate && !by_neighbour && !by_travel) {
                still_coasting = std::max(still_coasting, speed_[b]);
                continue;
            }
            coasting_[b] = 0;
            ++(by_promise     ? counts_.wakes_by_promise
               : by_plate     ? counts_.wakes_by_plate
               : by_neighbour ? counts_.wakes_by_neighbour
                              : counts_.wakes_by_travel);
        }
        awake_.push_back(b);
    }
    // Bodies that begin to coast at this step's end raise it again (begin_coasts).
    coasting_fastest_ = still_coasting;

    // Fly: a body awake at the last step by one step, exactly as CpuBackend does; one that wakes
    // now from its coast's start in one jump.
    const double dt = context.dt, gravity = context.gravity, drop = context.drop();
    const PeriodicBox2D box = context.box;
    const auto flown = static_cast<std::ptrdiff_t>(awake_.size());
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1)
    for (std::ptrdiff_t i = 0; i < flown; ++i) {
        const std::uint32_t b = awake_[static_cast<std::size_t>(i)];
        const physics::Rotor& rotor = species_.rotor[bodies.species[b]];
        const std::uint64_t steps = s - since_[b];
        if (steps == 1)
            physics::fly_freely(bodies.position[b], bodies.velocity[b], bodies.orientation[b],
                                bodies.spin[b], rotor, dt, gravity, drop, box);
        else
            physics::fly_for(bodies.position[b], bodies.velocity[b], bodies.orientation[b],
                             bodies.spin[b], rotor, steps, dt, gravity, box);
        since_[b] = s;
        placed_step_[b] = s;
    }
}

void CoastingBackend::place_coasting_spheres(const StepContext& context) {
    const auto n = static_cast<std::ptrdiff_t>(bodies_.size());
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        const auto b = static_cast<std::uint32_t>(i);
        if (!coasting_[b]) continue;
        Vec3 x, v, w;
        Quat q;
        fly_to(b, context.step, x, v, q, w);
        spheres_.place(b, bodies_.species[b], x, q, species_);
        placed_step_[b] = context.step;
    }
    ++counts_.refreshes;
}

void CoastingBackend::rebuild_partners() {
    const VerletPairList& list = finder_.pairs();
    if (partners_of_build_ == list.builds()) return;
    partners_of_build_ = list.builds();
    const std::size_t n = spheres_.size();
    partner_start_.assign(n + 1, 0);
    list.for_each_pair(spheres_.position, [&](std::uint32_t i, std::uint32_t j, const Vec3&) {
        ++partner_start_[i + 1];
        ++partner_start_[j + 1];
    });
    for (std::size_t i = 0; i < n; ++i)
        partner_start_[i + 1] += partner_start_[i];
    partners_.resize(partner_start_[n]);
    partner_fill_.assign(partner_start_.begin(), partner_start_.end() - 1);
    list.for_each_pair(spheres_.position, [&](std::uint32_t i, std::uint32_t j, const Vec3&) {
        partners_[partner_fill_[i]++] = j;
        partners_[partner_fill_[j]++] = i;
    });
}

int CoastingBackend::try_to_coast(std::uint32_t b, const StepContext& context, double fastest) {
    const std::uint64_t s = context.step;
    const double dt = context.dt;
    const Vec3& x = bodies_.position[b];
    const Vec3& w = bodies_.spin[b];
    // The plate bound holds for the whole free flight it was worked out from, until the body's
    // next contact: once per flight, not once per coast.
    if (!plate_known_[b] || plate_wake_[b] < s + kShortestCoast) {
        physics::CoastStart start;
        start.z = x.z;
        start.vz = bodies_.velocity[b].z;
        double lowest = x.z, highest = x.z;
        for (std::uint32_t sp = spheres_.first_of[b]; sp < spheres_.first_of[b + 1]; ++sp) {
            lowest = std::min(lowest, spheres_.position[sp].z - spheres_.radius[sp]);
            highest = std::max(highest, spheres_.position[sp].z + spheres_.radius[sp]);
        }
        start.below = x.z - lowest;
        start.above = highest - x.z;
        // Each sphere's height above the centre changes no faster than it turns about it.
        start.tilt_rate = turn_rate(b, bodies_.orientation[b], w);
        plate_wake_[b] = physics::first_plate_step(start, s, kPlateHorizon, dt, context.gravity,
                                                   context.plate_motion);
        plate_known_[b] = 1;
    }
    if (plate_wake_[b] < s + kShortestCoast) return 2;

    // Coasting, its speed in space grows by g τ unwatched: within the windows of the coasts that
    // rely on it (at most kLongestReliance from now) it must keep its promise.
    if (promise3_[b] != kNoPromise &&
        !(speed3_[b] + context.gravity * kLongestReliance <= promise3_[b]))
        return 5;
    // Pairs beyond the list: kSkin apart at its build, each sphere moved at most slack() since.
    const VerletPairList& pairs = finder_.pairs();
    const double far = pairs.skin() - 2.0 * pairs.slack();
    if (!(far > 2.0 * static_cast<double>(kShortestCoast) * fastest * dt + 2.0 * kTravelUnit))
        return 4;
    // The near ones, each in one of two ways.
    // - A calm neighbour (no contact for kCalmSteps steps) is relied on to keep its free flight:
    //   the two bodies' relative motion is then known, d(τ) = d₀ + Δv τ between two sphere
    //   centres (gravity pulls both alike) up to their turning, at most R τ with R the sum of
    //   each one's reach times |ω × u|; a sphere pair cannot touch while |d₀ + Δv τ| − R τ stays
    //   above r_i + r_j (in space, or in the plane: either keeps them apart). Its first contact
    //   wakes the coast at the next step; a plate projection may have moved it by the depth of
    //   that contact first, at most one step's approach to the plate, kept as a margin.
    // - Any other neighbour promises a speed bound (see the header): each gap closes no faster
    //   than the two spheres' speed bounds summed, in the plane or in space; the coasting body's
    //   own in space grows by g τ as it falls, so such a reliance lasts at most
    //   kLongestReliance.
    const double g = context.gravity;
    const double own = speed_[b], own3 = speed3_[b] + g * kLongestReliance;
    const Vec3 own_velocity = bodies_.velocity[b];
    const double own_turn = turn_rate(b, bodies_.orientation[b], bodies_.spin[b]);
    const double plate_speed =
        context.plate_motion.amplitude * context.plate_motion.angular_frequency;
    double reliance = kLongestFlight;  // s
    near_.clear();
    near_places_.clear();
    for (std::uint32_t i = spheres_.first_of[b]; i < spheres_.first_of[b + 1]; ++i) {
        const Vec3& p = spheres_.position[i];
        const double r = spheres_.radius[i];
        for (std::uint32_t m = partner_start_[i]; m < partner_start_[i + 1]; ++m) {
            const std::uint32_t j = partners_[m];
            const std::uint32_t other = spheres_.body[j];
            if (near_slot_[other] == 0) {
                Near n;
                n.body = other;
                n.flight = touched_at_[other] + kCalmSteps <= s;
                if (n.flight) {
                    Vec3 at, v, spin;
                    Quat q;
                    fly_to(other, s, at, v, q, spin);  // itself where it is awake
                    n.velocity = v;
                    n.turn = turn_rate(other, q, spin);
                    // One step's approach to a plate: the deepest a first plate contact goes.
                    n.projection = (std::abs(v.z) + g * kLongestFlight + n.turn + plate_speed) * dt;
                    if (coasting_[other]) {  // its spheres where it is now
                        n.places = static_cast<std::uint32_t>(near_places_.size());
                        const std::uint32_t first = spheres_.first_of[other];
                        near_places_.resize(near_places_.size() + spheres_.first_of[other + 1] -
                                            first);
                        const std::uint32_t k_other = bodies_.species[other];
                        physics::place_spheres(
                            near_places_.data() + n.places,
                            species_.sphere_offset.data() + species_.first_sphere[k_other],
                            spheres_.first_of[other + 1] - first, at, q,
                            species_.sphere_axis[k_other]);
                    }
                } else if (!promised_speeds(other, s, dt, g, n)) {
                    for (const Near& listed : near_)
                        near_slot_[listed.body] = 0;
                    return 5;
                }
                near_.push_back(n);
                near_slot_[other] = static_cast<std::uint32_t>(near_.size());
            }
            Near& n = near_[near_slot_[other] - 1];
            const Vec3& q = n.places == kNoPlaces
                                ? spheres_.position[j]
                                : near_places_[n.places + (j - spheres_.first_of[other])];
            const Vec3 d = context.box.minimum_image(p - q);
            const double reach = r + spheres_.radius[j] + physics::kCoastMargin;
            double open = 0.0;  // s
            if (n.flight) {
                if (!(std::sqrt(d.x * d.x + d.y * d.y) - reach < far)) continue;  // far bound's
                const Vec3 dv = own_velocity - n.velocity;
                const double turn = own_turn + n.turn, apart = reach + n.projection;
                open = std::max(first_reach(d, dv, turn, apart),
                                first_reach({d.x, d.y, 0.0}, {dv.x, dv.y, 0.0}, turn, apart));
            } else {
                const double planar_gap = std::sqrt(d.x * d.x + d.y * d.y) - reach - n.moved_planar;
                if (!(planar_gap < far)) continue;  // the far bound covers it
                const double space_gap = norm(d) - reach - n.moved_space;
                const double in_plane = planar_gap > 0.0 ? planar_gap / (own + n.planar) : 0.0;
                const double in_space = space_gap > 0.0 ? space_gap / (own3 + n.space) : 0.0;
                open = std::min(std::max(in_plane, in_space), kLongestReliance);
            }
            reliance = open >= 0.0 ? std::min(reliance, open) : 0.0;  // NaN: no coast
            n.relied_on = true;
        }
    }
    for (const Near& n : near_)
        near_slot_[n.body] = 0;
    const std::uint64_t neighbour_wake = s + steps_within(reliance, dt);
    if (neighbour_wake < s + kShortestCoast) return 3;

    // It coasts: the neighbours' flights watched and promises made, its reliance noted.
    ++generation_[b];
    for (const Near& n : near_) {
        if (!n.relied_on) continue;
        const std::uint32_t j = n.body;
        if (!n.flight) {
            promise_[j] = n.planar;
            promise3_[j] = n.space;
        }
        std::vector<Watch>& list = n.flight ? flight_watchers_[j] : watchers_[j];
        if (list.size() >= 16)  // drop the coasts that have ended
            std::erase_if(list, [&](const Watch& watch) {
                return !coasting_[watch.body] || generation_[watch.body] != watch.generation;
            });
        list.push_back({b, generation_[b]});
    }
    neighbour_wake_[b] = neighbour_wake;
    // Far bodies: wakes once T − T(s) reaches half the clearance: before, neither it nor any
    // other sphere moved half of it in the plane. T rounds up, this threshold down.
    travel_wake_[b] =
        saturating_add(travel_, static_cast<std::uint64_t>(std::floor(0.5 * far / kTravelUnit)));
    coasting_[b] = 1;
    placed_step_[b] = s;
    coasting_fastest_ = std::max(coasting_fastest_, own);
    return 1;
}

void CoastingBackend::begin_coasts(const StepContext& context, double fastest) {
    const std::uint64_t s = context.step;
    // A contact ends the body's free flight: its plate bound goes, and so do the coasts that
    // relied on the flight (they wake at the next step, before anything moves).
    const auto flight_ends = [&](std::uint32_t j) {
        touched_[j] = 1;
        plate_known_[j] = 0;
        touched_at_[j] = s;
        for (const Watch& w : flight_watchers_[j])
            if (coasting_[w.body] && generation_[w.body] == w.generation) coasting_[w.body] = 2;
        flight_watchers_[j].clear();
    };
    for (const Contact& c : contacts_) {
        flight_ends(c.a);
        if (!c.with_plate()) flight_ends(c.b);
    }
    candidates_.clear();
    for (const std::uint32_t b : awake_)
        if (!touched_[b] && s >= next_try_[b]) candidates_.push_back(b);
    for (const Contact& c : contacts_) {
        touched_[c.a] = 0;
        if (!c.with_plate()) touched_[c.b] = 0;
    }
    if (candidates_.empty()) return;
    rebuild_partners();
    // In body order, one after another: a coast's promises are the next one's to rely on.
    for (const std::uint32_t b : candidates_) {
        const int outcome = try_to_coast(b, context, fastest);
        if (outcome == 1) {
            failures_[b] = 0;
            ++counts_.coasts;
            continue;
        }
        // Trying again costs as much as the first try: a body that keeps failing waits longer.
        next_try_[b] = s + (kRetrySteps << std::min<int>(failures_[b], 3));
        failures_[b] = static_cast<std::uint8_t>(std::min(failures_[b] + 1, 255));
        ++(outcome == 2   ? counts_.near_plate
           : outcome == 3 ? counts_.near_body
           : outcome == 4 ? counts_.far_body
                          : counts_.fast_neighbour);
    }
}

void CoastingBackend::step(const StepContext& context, StepStatistics& stats,
                           StageProfile& profile) {
    if (counts_.steps == 0) {
        // The state is at the step before this one (a resumed run starts at its checkpoint's).
        std::fill(since_.begin(), since_.end(), context.step - 1);
        awake_.resize(bodies_.size());
        for (std::uint32_t b = 0; b < bodies_.size(); ++b)
            awake_[b] = b;
    }
    flight_ = {context.dt, context.gravity, context.box};
    const BodyView bodies = bodies_.view();
    double fastest = 0.0;
    {
        StageTimer t(profile.free_flight);
        wake_and_fly(context, fastest);
    }
    {
        StageTimer t(profile.sphere_update);
        spheres_.update_positions_of(awake_, bodies, species_, threads_);
        // The list about to measure how far every sphere moved needs the coasting ones too.
        if (finder_.pairs().looks_after(fastest * context.dt)) place_coasting_spheres(context);
    }
    ContactSearchStats found;
    {
        StageTimer t(profile.contact_search);
        found = finder_.find_awake(spheres_, bodies, species_, context, awake_, coasting_,
                                   contacts_, threads_, fastest * context.dt);
    }
    stats = response_.respond(contacts_, bodies, species_, spheres_, context, threads_, profile,
                              found, fastest, awake_.size());
    counts_.awake_body_steps += awake_.size();
    ++counts_.steps;
    {
        StageTimer t(profile.free_flight);
        begin_coasts(context, fastest);
    }
    step_ = context.step;
}

const BodyState& CoastingBackend::bodies() const {
    if (current_at_ == step_) return current_;
    current_ = bodies_;
    for (std::uint32_t b = 0; b < bodies_.size(); ++b)
        if (coasting_[b])
            fly_to(b, step_, current_.position[b], current_.velocity[b], current_.orientation[b],
                   current_.spin[b]);
    current_at_ = step_;
    return current_;
}

SphereView CoastingBackend::spheres() const {
    if (current_spheres_at_ != step_) {
        current_spheres_ = spheres_;
        for (std::uint32_t b = 0; b < bodies_.size(); ++b) {
            if (!coasting_[b]) continue;
            Vec3 x, v, w;
            Quat q;
            fly_to(b, step_, x, v, q, w);
            current_spheres_.place(b, bodies_.species[b], x, q, species_);
        }
        current_spheres_at_ = step_;
    }
    return current_spheres_.view();
}

}  // namespace rodsea::cpu
