#pragma once
// What the data-parallel step keeps of each system between its kernels and over a run of steps,
// in the executor's memory, so that a device takes many steps without the host reading anything
// (parallel_ensemble.hpp): each step's counts, gathered by the step's elements with integer
// atomics and maxima (the same whatever order they run in); each system's run so far, with its
// stop after a step that crossed its blow-up bounds; and the words every system shares.
#include <cmath>
#include <cstdint>

#include "rodsea/engine/parallel/atomics.hpp"
#include "rodsea/engine/step_backend.hpp"
#include "rodsea/math/hostdevice.hpp"

namespace rodsea::parallel {

// One step of one system, as its elements count it. Maxima as ordered_bits (atomics.hpp).
struct StepCounts {
    std::uint64_t body_contacts = 0;
    std::uint64_t plate_contacts = 0;
    std::uint64_t sweeps = 0;  // the most any island took
    std::uint64_t impulses = 0;
    std::uint64_t body_collisions = 0;
    std::uint64_t plate_collisions = 0;
    std::uint64_t unresolved = 0;  // contacts still approaching at the sweep cap
    std::uint64_t gross = 0;       // contacts deeper than the gross overlap fraction
    std::uint64_t noise_kicks = 0;
    std::uint64_t overlap_bits = 0;  // the deepest contact over its smaller radius
    std::uint64_t drift2_bits = 0;   // the fastest body's squared in-plane speed, mm²/s²
    std::uint64_t turn2_bits = 0;    // the fastest-turning body's bound on its spheres', mm²/s²

    // The CPU backend's statistics of the same step.
    RODSEA_HD StepStatistics statistics() const {
        StepStatistics s;
        s.body_contacts = body_contacts;
        s.plate_contacts = plate_contacts;
        s.sweeps = static_cast<int>(sweeps);
        s.impulses = impulses;
        s.body_collisions = body_collisions;
        s.plate_collisions = plate_collisions;
        s.unresolved = unresolved + gross;
        s.noise_kicks = noise_kicks;
        s.max_overlap_fraction = from_ordered_bits(overlap_bits);
        s.max_planar_speed =
            std::sqrt(from_ordered_bits(drift2_bits)) + std::sqrt(from_ordered_bits(turn2_bits));
        return s;
    }
};

// When a system stops within a run: after a step that crosses `bounds`, if `active`.
struct HaltBounds {
    BlowUpBounds bounds;
    std::uint32_t active = 0;
};

// One system's run of steps so far.
struct SystemRun {
    std::uint64_t steps = 0;
    std::uint32_t halted = 0;  // its last step crossed its bounds: it takes no more in this run
    StepStatistics last;
    StepTally tally;

    // The end of a step: its counts become the last step's statistics, join the tally and are
    // cleared for the next step.
    RODSEA_HD void end_step(StepCounts& counts, const HaltBounds& halt) {
        last = counts.statistics();
        tally.add(last);
        ++steps;
        if (halt.active != 0 && halt.bounds.crossed_by(last)) halted = 1;
        counts = StepCounts{};
    }
};

// The words every system of a run shares.
struct RunStatus {
    std::uint32_t step = 0;     // the step of the run being taken, from 0: which contexts it reads
    std::uint32_t steps = 0;    // the run's length
    std::uint32_t rebuild = 0;  // this step builds the neighbour list anew
    std::uint32_t force_rebuild = 0;  // the next step must (a new list, or a state put back)
    std::uint64_t builds = 0;         // of the neighbour list, since the stepper was made
    // The step's contacts: places handed out as spheres find theirs (every system's, in no
    // particular order: contact_key orders them), and once every sphere has, how many there
    // are (0 when they did not fit: the run is then taken again, with more room).
    std::uint32_t placed = 0;
    std::uint32_t contacts = 0;
    std::uint32_t island_placed = 0;  // places handed out to the islands' sweeps
    // Room asked for beyond what there was, in this run (0: it all fitted): the most partners a
    // sphere had in the neighbour list, the most contacts a step had, the most spheres a cell
    // held.
    std::uint64_t needed_slots = 0;
    std::uint64_t needed_contacts = 0;
    std::uint64_t needed_cell_room = 0;
};

}  // namespace rodsea::parallel
