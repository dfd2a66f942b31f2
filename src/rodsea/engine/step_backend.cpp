#include "rodsea/engine/step_backend.hpp"

#include <algorithm>

namespace rodsea {

void StepTally::add(const StepTally& other) {
    steps += other.steps;
    impulses += other.impulses;
    body_collisions += other.body_collisions;
    plate_collisions += other.plate_collisions;
    unresolved += other.unresolved;
    noise_kicks += other.noise_kicks;
    body_steps += other.body_steps;
    max_sweeps = std::max(max_sweeps, other.max_sweeps);
    max_overlap_fraction = std::max(max_overlap_fraction, other.max_overlap_fraction);
}

StepsDone StepBackend::run_steps(std::span<const StepContext> contexts, const BlowUpBounds* bounds,
                                 StageProfile& profile) {
    StepsDone done;
    for (const StepContext& context : contexts) {
        step(context, done.last, profile);
        ++done.steps;
        done.tally.add(done.last);
        if (bounds != nullptr && bounds->crossed_by(done.last)) {
            done.blew_up = true;
            break;
        }
    }
    return done;
}

}  // namespace rodsea
