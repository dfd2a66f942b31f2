#pragma once
// The CPU step that flies only the bodies that can touch something (BackendOptions::coasting).
//
// Between its collisions a body's motion is exact: a parabola and a torque-free rotation. A
// body that ends a step touching nothing, and cannot reach a plate or another body for a while,
// *coasts*: it is left alone (not flown, its spheres not placed, its pairs not looked at) until
// the first step at which it might touch something, and is then flown there in one jump
// (physics::fly_for). The step is otherwise CpuBackend's, over the awake bodies: the same stages,
// the same contact tests at the same step boundaries, the same impulses and noise.
//
// A coast ends (the wake-up) at the first step one of these conservative bounds cannot clear:
// - the plates: physics::first_plate_step, from the body's own exact flight and the plates'
//   known motion;
// - its near neighbours, the bodies whose spheres its own list of pairs (skin kSkin) holds. A
//   calm neighbour (no contact for kCalmSteps steps) is relied on to keep its free flight: their
//   relative motion is then known up to their turning (gravity pulls both alike), and a sphere
//   pair stays apart while |d₀ + Δv τ| − R τ exceeds the sum of the radii; the neighbour's next
//   contact wakes the coast. Any other neighbour *promises* a speed bound (1.5 times its own
//   plus 10 mm/s), in the plane and in space, and each gap closes no faster than the two
//   bodies' bounds summed; every step compares each awake body's speed bounds with its promise,
//   and one that breaks it wakes every coast that relied on it, before anything moves;
// - everything else: T(k), the sum over steps of the step's bound on every sphere's speed in the
//   plane, bounds how far any sphere moved in the plane from step s₀ to k by T(k) − T(s₀).
//   Pairs the list does not hold are at least kSkin − 2 slack apart in the plane, beyond their
//   radii, and cannot touch while 2 (T(k) − T(s₀)) is less than that.
// Nothing the step-by-step scheme would find is missed, up to the trajectory's round-off: the
// jump and the per-step flight agree to round-off, not to the bit (tests/test_coasting.cpp).
//
// The state handed out (bodies(), spheres()) is every body at the current step: a coasting body
// is flown there in a copy, so looking never changes the trajectory. Deterministic on any number
// of threads: every decision is a function of the state and the step number. A run resumed from
// a checkpoint starts with every body awake, so it follows the uninterrupted run statistically,
// not bit for bit (docs/performance.md, Coasting).
#include <cstdint>
#include <vector>

#include "rodsea/engine/cpu/contact_response.hpp"
#include "rodsea/engine/cpu/contact_search.hpp"
#include "rodsea/engine/cpu/sphere_table.hpp"
#include "rodsea/engine/species_table.hpp"
#include "rodsea/engine/step_backend.hpp"
#include "rodsea/neighbors/verlet_pair_list.hpp"

namespace rodsea::cpu {

// What the coasting did, over the backend's life.
struct CoastingCounts {
    std::uint64_t steps = 0;
    std::uint64_t awake_body_steps = 0;  // bodies flown, placed and searched, summed over steps
    std::uint64_t coasts = 0;            // coasts begun
    // Tries that did not coast: a plate or a near neighbour too near for a coast worth
    // beginning, the far bound spent, a neighbour that could not promise.
    std::uint64_t near_plate = 0, near_body = 0, far_body = 0, fast_neighbour = 0;
    // Why coasts ended: a plate, a near neighbour's gap, a far body (T), a neighbour's broken
    // promise or ended flight.
    std::uint64_t wakes_by_plate = 0, wakes_by_neighbour = 0, wakes_by_travel = 0,
                  wakes_by_promise = 0;
    std::uint64_t refreshes = 0;  // coasting spheres placed for the list's check
};

class CoastingBackend final : public StepBackend {
  public:
    // `species` must outlive the backend. threads >= 1 (checked by Simulation).
    CoastingBackend(const SpeciesTable& species, BodyState bodies, int threads);

    const char* name() const override { return "cpu"; }
    void step(const StepContext& context, StepStatistics& stats, StageProfile& profile) override;
    const BodyState& bodies() const override;
    SphereView spheres() const override;
    const std::vector<Contact>& contacts() const override { return contacts_; }
    void set_threads(int threads) override { threads_ = threads; }
    std::uint64_t pair_list_builds() const override { return finder_.pair_list_builds(); }

    const CoastingCounts& counts() const { return counts_; }

  private:
    // One unit of T, the summed travel bound, in mm: an integer sum is exact, in any order.
    static constexpr double kTravelUnit = 1e-10;
    // The skin of its list of pairs (mm), twice CpuBackend's: the near neighbours come from it,
    // and a coast lasts at most about kSkin / 4 of travel at the fastest body's speed before
    // the bodies beyond might arrive. 0.1 mm measured best of 0.1, 0.15 and 0.2, and of a
    // second, thicker list beside CpuBackend's (docs/performance.md, Coasting): the awake
    // bodies' search reads more pairs, and the list is rebuilt, more than longer coasts save.
    static constexpr double kSkin = 2.0 * kVerletSkin;

    void wake_and_fly(const StepContext& context, double& fastest);
    void place_coasting_spheres(const StepContext& context);
    void begin_coasts(const StepContext& context, double fastest);
    // Tries to begin a coast of awake body b at the end of the step; returns 1 if it does, 2 if
    // a plate is too near, 3 if a body is, 4 if the list's far bound is spent, 5 if a
    // neighbour cannot promise (it has broken its promise, or would coasting on).
    int try_to_coast(std::uint32_t b, const StepContext& context, double fastest);
    // Body b's state flown from the step of its entry in bodies_ to `step`.
    void fly_to(std::uint32_t b, std::uint64_t step, Vec3& x, Vec3& v, Quat& q, Vec3& w) const;
    // Bounds on the speed of its spheres from its state, mm/s: in the plane and in space.
    struct Speeds {
        double planar, space;
    };
    Speeds speed_bounds(std::uint32_t b) const;
    void rebuild_partners();
    double turn_rate(std::uint32_t b, const Quat& q, const Vec3& w) const;

    // What a jump needs of the steps (the same every step).
    struct Flight {
        double dt = 0.0, gravity = 0.0;
        PeriodicBox2D box;
    };
    Flight flight_;

    const SpeciesTable& species_;
    BodyState bodies_;  // a coasting body's entry is its state at its coast's start
    int threads_;

    // Per body.
    std::vector<std::uint8_t> coasting_;
    std::vector<std::uint64_t> since_;  // the step its entry in bodies_ is at
    // The first step it might touch a plate, from the start of its present free flight, and
    // whether that is still its flight (no contact since).
    std::vector<std::uint64_t> plate_wake_;
    std::vector<std::uint8_t> plate_known_;
    std::vector<std::uint64_t> neighbour_wake_;  // first step a near neighbour might touch it
    std::vector<std::uint64_t> travel_wake_;     // T at which a far body might touch it
    std::vector<std::uint64_t> placed_step_;     // when its spheres were last placed
    std::vector<std::uint64_t> next_try_;        // step before which it does not try to coast
    std::vector<std::uint8_t> failures_;         // tries in a row that did not coast
    // Its spheres' speed bounds, in the plane and in space: this step's, or its coast's start's.
    std::vector<double> speed_, speed3_;
    std::vector<std::uint32_t> generation_;   // coasts begun, to tell a present coast
    std::vector<double> promise_, promise3_;  // mm/s, in the plane and in space; ∞: none
    struct Watch {
        std::uint32_t body, generation;
    };
    std::vector<std::vector<Watch>> watchers_;         // the coasts relying on its promise
    std::vector<std::vector<Watch>> flight_watchers_;  // the coasts relying on its free flight
    std::vector<std::uint64_t> touched_at_;            // the step of its last contact
    std::vector<std::uint8_t> touched_;                // in a contact this step
    std::vector<std::uint32_t> awake_;                 // ascending
    std::vector<std::uint32_t> broken_;                // promises broken this step
    std::uint64_t travel_ = 0;                         // T, in kTravelUnit
    double coasting_fastest_ = 0.0;  // a bound on the planar speed of every coasting body, mm/s
    std::uint64_t step_ = 0;         // the last step taken

    // Each sphere's partners in the list of pairs, both ways (the list holds each pair once).
    std::uint64_t partners_of_build_ = 0;
    std::vector<std::uint32_t> partner_start_, partners_, partner_fill_;
    // A near neighbour of the body trying to coast, relied on to keep its free flight (its
    // velocity, turn rate R and projection margin, its spheres' places now where it coasts:
    // index into near_places_) or its promised speeds (and how far it may have moved since its
    // spheres were placed); and whether a gap to it was near enough to rely on it.
    static constexpr std::uint32_t kNoPlaces = ~std::uint32_t{0};
    struct Near {
        std::uint32_t body = 0;
        bool flight = false;
        Vec3 velocity;
        double turn = 0.0, projection = 0.0;
        std::uint32_t places = kNoPlaces;
        double planar = 0.0, space = 0.0;
        double moved_planar = 0.0, moved_space = 0.0;
        bool relied_on = false;
    };
    std::vector<Vec3> near_places_;
    bool promised_speeds(std::uint32_t j, std::uint64_t s, double dt, double g, Near& n) const;
    std::vector<Near> near_;
    std::vector<std::uint32_t> near_slot_;  // per body: its index in near_ plus one, or 0

    // Scratch reused every step.
    SphereTable spheres_;
    ContactFinder finder_;
    std::vector<Contact> contacts_;
    ContactResponse response_;
    std::vector<std::uint32_t> candidates_;

    // The state handed out: every body at step_, made when asked.
    mutable BodyState current_;
    mutable SphereTable current_spheres_;
    mutable std::uint64_t current_at_ = ~std::uint64_t{0};
    mutable std::uint64_t current_spheres_at_ = ~std::uint64_t{0};

    CoastingCounts counts_;
};

}  // namespace rodsea::cpu
